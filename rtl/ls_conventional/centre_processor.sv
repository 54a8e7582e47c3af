// centre_processor: the row-parallel centre processor of ls-conventional (thesis [31]). One
// instance listens to one row's address_search. Views of the same block:
// systemc/ls_conventional/centre_processor_kernel.h (cycle kernel, bit- and cycle-exact to this file) and
// systemc/ls_conventional/centre_processor.h (sc_module).
//
// Every cycle with addr_valid_i it shifts in addr_bit_i (left address, then right, MSB first,
// ADDRESS_BITS each); the edge that takes the last of the 2 B bits adds (left + right) to sum_q
// and counts the sampling (count_q). clear_i (the sequencer's reset phase) clears everything at
// the end of its cycle and wins over a stream bit. Outputs are combinational from the registers:
//   valid_o    = count > 0
//   centre_q_o = floor((sum * 2^8 + n) / (2 n))   Q(ADDRESS_BITS).8, ties up; 0 when n = 0
// which is the kernel's CentreProcessorPins. SAMPLINGS bounds n per frame access and sizes the
// registers; a sampling beyond it is a protocol error (a_count_no_wrap), never a silent wrap.
`timescale 1ns / 1ps  // must match the SystemC time resolution (1 ps, the SystemC default)

module centre_processor #(
    parameter int ADDRESS_BITS = 9,  // width of a streamed column address
    parameter int SAMPLINGS    = 4,  // most detecting samplings between two clears
    // Derived widths (do not override): n, sum of (left + right) over n, Q(B).8 centre.
    parameter int CountBits    = $clog2(SAMPLINGS + 1),
    parameter int SumBits      = ADDRESS_BITS + 1 + $clog2(SAMPLINGS + 1),
    parameter int CentreBits   = ADDRESS_BITS + 8
) (
    input  logic                  clk,
    input  logic                  rst,           // synchronous, active high
    input  logic                  clear_i,       // clear the accumulator (sequencer reset phase)
    input  logic                  addr_valid_i,  // from address_search addr_valid_o
    input  logic                  addr_bit_i,    // from address_search addr_bit_o
    output logic                  valid_o,       // at least one detecting sampling
    output logic [CentreBits-1:0] centre_q_o,    // centre, Q(ADDRESS_BITS).8
    output logic [   SumBits-1:0] sum_o,         // sum of (left + right)
    output logic [ CountBits-1:0] count_o        // detecting samplings n
);
  localparam int StreamBits = 2 * ADDRESS_BITS;
  localparam int BitCountBits = $clog2(StreamBits + 1);

  logic [StreamBits-2:0] shift_q;  // the first 2B-1 bits of the current stream, newest in bit 0
  logic [BitCountBits-1:0] bits_q;  // how many of them
  logic [SumBits-1:0] sum_q;
  logic [CountBits-1:0] count_q;

  // The stream completes at this edge: the previous 2B-1 bits and this one.
  wire last_bit = addr_valid_i && (bits_q == BitCountBits'(StreamBits - 1));
  wire [StreamBits-1:0] stream_c = {shift_q, addr_bit_i};
  wire [ADDRESS_BITS:0] pair_c = {1'b0, stream_c[StreamBits-1:ADDRESS_BITS]} +
                                 {1'b0, stream_c[ADDRESS_BITS-1:0]};

  always_ff @(posedge clk) begin
    if (rst || clear_i) begin
      shift_q <= '0;
      bits_q  <= '0;
      sum_q   <= '0;
      count_q <= '0;
    end else if (addr_valid_i) begin
      if (last_bit) begin
        shift_q <= '0;
        bits_q  <= '0;
        sum_q   <= sum_q + SumBits'(pair_c);
        count_q <= count_q + 1'b1;
      end else begin
        shift_q <= stream_c[StreamBits-2:0];
        bits_q  <= bits_q + 1'b1;
      end
    end
  end

  // Centre = (sum * 256 + n) / (2 n), rounded to nearest with ties up. A combinational divider
  // is fine at this size (n <= SAMPLINGS); silicon would run it during the output phase.
  localparam int NumBits = SumBits + 8 + 1;
  wire [NumBits-1:0] num_c = {1'b0, sum_q, 8'd0} + NumBits'(count_q);
  wire [NumBits-1:0] den_c = NumBits'({count_q, 1'b0});
  // The quotient is at most 2^B - 1 + 1/2 in Q.8, so it fits CentreBits.
  wire [CentreBits-1:0] quot_c = (count_q != '0) ? CentreBits'(num_c / den_c) : '0;

  assign valid_o    = (count_q != '0);
  assign centre_q_o = quot_c;
  assign sum_o      = sum_q;
  assign count_o    = count_q;

  // ---- Assertions (simulation only; Icarus 11 rejects labelled immediate assertions) ----
`ifndef SYNTHESIS
  wire count_full = (count_q == CountBits'(SAMPLINGS));
  wire clear_mid_stream = clear_i && addr_valid_i && (bits_q != '0);
  always @(posedge clk) begin
    if (!rst) begin
`ifdef __ICARUS__
      if (last_bit && !clear_i && count_full) $error("a_count_no_wrap: more than SAMPLINGS streams");
      if (clear_mid_stream) $error("a_no_clear_mid_stream: clear during an address stream");
`else
      a_count_no_wrap : assert (!(last_bit && !clear_i && count_full))
      else $error("more than SAMPLINGS streams between clears");
      a_no_clear_mid_stream : assert (!clear_mid_stream)
      else $error("clear during an address stream");
`endif
    end
  end
`endif
endmodule
