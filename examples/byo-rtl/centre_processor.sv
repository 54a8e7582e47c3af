// An alternative implementation of rangesim's centre_processor block, written from its port
// contract (docs/rtl-contract.md) alone, as a user's RTL would be: it receives one row's two
// bit-serial edge addresses per sampling, accumulates left + right over the samplings of a frame
// access, and presents the count, the sum and the centre in Q(ADDRESS_BITS).8.
//
// Unlike rangesim's own (one 2B-bit shift register), this one fills a left and a right address
// register in turn and adds when the right one is complete. Run it in the ls-conventional readout:
//   rangesim cosim ls-conventional --rtl examples/byo-rtl/centre_processor.sv
`timescale 1ns / 1ps

module centre_processor #(
    parameter int ADDRESS_BITS = 9,
    parameter int SAMPLINGS    = 4,
    parameter int CountBits    = $clog2(SAMPLINGS + 1),
    parameter int SumBits      = ADDRESS_BITS + 1 + $clog2(SAMPLINGS + 1),
    parameter int CentreBits   = ADDRESS_BITS + 8
) (
    input  logic                  clk,
    input  logic                  rst,
    input  logic                  clear_i,
    input  logic                  addr_valid_i,
    input  logic                  addr_bit_i,
    output logic                  valid_o,
    output logic [CentreBits-1:0] centre_q_o,
    output logic [   SumBits-1:0] sum_o,
    output logic [ CountBits-1:0] count_o
);
  localparam int IndexBits = $clog2(ADDRESS_BITS + 1);

  logic [ADDRESS_BITS-1:0] left_q;   // the left address, MSB first
  logic [ADDRESS_BITS-2:0] right_q;  // the bits of the right address before its last
  logic                    on_right_q;       // the right address is arriving
  logic [   IndexBits-1:0] index_q;          // bits of the current address received
  logic [     SumBits-1:0] total_q;
  logic [   CountBits-1:0] samplings_q;

  wire                    address_done = (index_q == IndexBits'(ADDRESS_BITS - 1));
  wire [ADDRESS_BITS-1:0] right_next = {right_q, addr_bit_i};
  wire [  ADDRESS_BITS:0] pair = {1'b0, left_q} + {1'b0, right_next};

  always_ff @(posedge clk) begin
    if (rst || clear_i) begin
      left_q      <= '0;
      right_q     <= '0;
      on_right_q  <= 1'b0;
      index_q     <= '0;
      total_q     <= '0;
      samplings_q <= '0;
    end else if (addr_valid_i) begin
      if (!on_right_q) left_q <= {left_q[ADDRESS_BITS-2:0], addr_bit_i};
      else right_q <= right_next[ADDRESS_BITS-2:0];
      if (address_done) begin
        index_q    <= '0;
        on_right_q <= !on_right_q;
        if (on_right_q) begin  // the pair is complete
          total_q     <= total_q + SumBits'(pair);
          samplings_q <= samplings_q + 1'b1;
          left_q      <= '0;
          right_q     <= '0;
        end
      end else begin
        index_q <= index_q + 1'b1;
      end
    end
  end

  // Centre in Q(B).8, rounded half up: floor((256 total + n) / (2 n)); 0 before any sampling.
  localparam int WideBits = SumBits + 9;
  wire [WideBits-1:0] scaled = WideBits'(total_q) * WideBits'(256) + WideBits'(samplings_q);
  wire [WideBits-1:0] twice_n = WideBits'(samplings_q) * WideBits'(2);

  assign valid_o    = |samplings_q;
  assign centre_q_o = valid_o ? CentreBits'(scaled / twice_n) : '0;
  assign sum_o      = total_q;
  assign count_o    = samplings_q;
endmodule
