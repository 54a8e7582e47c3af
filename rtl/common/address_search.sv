// address_search: row-parallel chained search with a bit-streamed column address (ls-conventional,
// thesis [31]). One instance is the search/stream logic of ONE row; the chip has one per row and
// starts them all with the same strobe. Views of the same block: systemc/common/address_search_kernel.h
// (cycle kernel, bit- and cycle-exact to this file) and systemc/common/address_search.h (sc_module).
// Parameters come from rangesim::AddressSearchConfig (COLUMNS, ADDRESS_BITS) and
// FrameTimingConfig::search_cycles (SEARCH_CYCLES).
//
// Behaviour: on `start_i` the comparator outputs `act_i` (bit c = column c activated) are
// latched. The chained search finds the leftmost (lowest column index) and rightmost (highest
// index) activated column; the chain needs SEARCH_CYCLES clock cycles to settle. Then the left
// address and then the right address are streamed bit-serially, MSB first, ADDRESS_BITS cycles
// each, on addr_bit_o qualified by addr_valid_o. Without an activated pixel nothing is streamed.
//
// Cycle schedule (cycle k = k-th clock period after the one in which start_i is high; every
// output is a function of registers, so it is stable for the whole cycle and is sampled at the
// rising edge that ends the cycle). S = SEARCH_CYCLES, B = ADDRESS_BITS:
//   k = 0            start_i = 1 (the FrameTimingConfig "latch" cycle); its end edge latches act_i
//   k = 1 .. S       search settles; busy_o = 1, addr_valid_o = 0; found_o valid from k = 1
//   k = S+1 .. S+B   addr_valid_o = 1, addr_bit_o = left[B-1-(k-S-1)]   (MSB first)
//   k = S+B+1..S+2B  addr_valid_o = 1, addr_bit_o = right[B-1-(k-S-B-1)]
//   k = S+2B         done_o = 1 (last stream cycle); next start_i allowed from k = S+2B+1
//   found_o = 0:     no stream, done_o = 1 at k = S; next start_i allowed from k = S+1
// So one sampling costs latch + S + 2B = 1 + 2 + 18 = 21 cycles at the defaults, which is what
// golden/common/frame_timing.h counts (addresses_per_sampling = 2). found_o holds until the next start.
//
// Reset is synchronous and active high. start_i while busy_o is a protocol error (assertion
// a_start_while_busy); it is ignored by the logic.
`timescale 1ns / 1ps  // must match the SystemC time resolution (1 ps, the SystemC default)

module address_search #(
    parameter int COLUMNS       = 375,  // pixels in the row
    parameter int ADDRESS_BITS  = 9,    // width of a streamed column address
    parameter int SEARCH_CYCLES = 2     // settle time of the chained search, >= 1
) (
    input  logic               clk,
    input  logic               rst,           // synchronous, active high
    input  logic               start_i,       // one-cycle strobe in the comparator latch cycle
    input  logic [COLUMNS-1:0] act_i,         // activation bits of the row, bit c = column c
    output logic               busy_o,        // an operation is in progress (start_i not allowed)
    output logic               found_o,       // at least one activated column (valid from k = 1)
    output logic               addr_valid_o,  // addr_bit_o carries an address bit
    output logic               addr_bit_o,    // left then right address, MSB first
    output logic               done_o         // last cycle of the operation
);
  localparam int CountMax  = (SEARCH_CYCLES > 2 * ADDRESS_BITS) ? SEARCH_CYCLES : 2 * ADDRESS_BITS;
  localparam int CountBits = $clog2(CountMax + 1);
  localparam int ShiftBits = 2 * ADDRESS_BITS;

  typedef enum logic [1:0] {
    IDLE   = 2'd0,
    SEARCH = 2'd1,
    STREAM = 2'd2
  } state_e;

  state_e                 state_q;
  logic   [CountBits-1:0] count_q;  // cycles spent in the current state
  logic   [  COLUMNS-1:0] act_q;  // latched activation bits (the pixels' comparator latches)
  logic   [ShiftBits-1:0] shift_q;  // {left, right}, shifted out MSB first

  // Chained search. In silicon a token ripples through the pixel chain (hence SEARCH_CYCLES);
  // here the settled value: the last assignment wins, so the downward loop leaves the lowest
  // activated index and the upward loop the highest.
  logic [ADDRESS_BITS-1:0] left_c, right_c;
  logic                    any_c;
  always_comb begin
    left_c  = '0;
    right_c = '0;
    for (int c = COLUMNS - 1; c >= 0; c--) if (act_q[c]) left_c = ADDRESS_BITS'(c);
    for (int c = 0; c < COLUMNS; c++) if (act_q[c]) right_c = ADDRESS_BITS'(c);
    any_c = |act_q;
  end

  wire search_last = (state_q == SEARCH) && (count_q == CountBits'(SEARCH_CYCLES - 1));
  wire stream_last = (state_q == STREAM) && (count_q == CountBits'(ShiftBits - 1));

  always_ff @(posedge clk) begin
    if (rst) begin
      state_q <= IDLE;
      count_q <= '0;
      act_q   <= '0;
      shift_q <= '0;
    end else begin
      count_q <= count_q + 1'b1;
      case (state_q)
        IDLE: begin
          count_q <= '0;
          if (start_i) begin
            act_q   <= act_i;
            state_q <= SEARCH;
          end
        end
        SEARCH: begin
          if (search_last) begin
            count_q <= '0;
            shift_q <= {left_c, right_c};
            state_q <= any_c ? STREAM : IDLE;
          end
        end
        STREAM: begin
          shift_q <= shift_q << 1;
          if (stream_last) begin
            count_q <= '0;
            state_q <= IDLE;
          end
        end
        default: state_q <= IDLE;
      endcase
    end
  end

  assign busy_o       = (state_q != IDLE);
  assign found_o      = any_c;
  assign addr_valid_o = (state_q == STREAM);
  assign addr_bit_o   = addr_valid_o & shift_q[ShiftBits-1];
  assign done_o       = (search_last && !any_c) || stream_last;

  // ---- Parameter checks and assertions (simulation only) ----
  // Icarus 11 rejects labelled immediate assertions, so it gets the same checks as plain ifs.
`ifndef SYNTHESIS
  // Bad parameters: Verilator stops at elaboration (so the build fails), Icarus at time 0.
  if (SEARCH_CYCLES < 1 || COLUMNS < 1 || ADDRESS_BITS < 1 || (1 << ADDRESS_BITS) < COLUMNS)
  begin : g_bad_parameters
`ifdef VERILATOR
    $error("address_search: need SEARCH_CYCLES >= 1 and 2**ADDRESS_BITS >= COLUMNS");
`else
    initial $fatal(1, "address_search: need SEARCH_CYCLES >= 1 and 2**ADDRESS_BITS >= COLUMNS");
`endif
  end

  always @(posedge clk) begin
    if (!rst) begin
`ifdef __ICARUS__
      if (start_i && busy_o) $error("a_start_while_busy: start_i while busy");
      if (addr_valid_o && !found_o) $error("a_stream_needs_found: stream without activation");
`else
      a_start_while_busy : assert (!(start_i && busy_o))
      else $error("start_i while busy");
      a_stream_needs_found : assert (!(addr_valid_o && !found_o))
      else $error("stream without activation");
`endif
    end
  end
`endif
endmodule
