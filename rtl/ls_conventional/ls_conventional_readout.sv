// ls_conventional_readout: the digital readout of the ls-conventional sensor (thesis [31]) as one
// block: the frame sequencer (multisampling_sequencer), and per row (generate) the comparator
// latches, the chained address search (address_search) and the centre processor
// (centre_processor). The pixel array (analog) stays outside: cmp_i carries the comparator
// decisions of every pixel. View of the same composition in C++:
// systemc/ls_conventional/sensor_kernel.h (and the sc_module systemc/ls_conventional/sensor.h),
// which this file matches cycle for cycle (tb/ls_conventional/cosim.cpp checks it).
//
// Comparator latch of row r: act_q[r] <= act_q[r] | cmp_i[r] at the end of every latch cycle,
// cleared in the reset phase, so an activated pixel stays activated for the frame access (the
// samplings are nested in time). The search start (last latch cycle) latches act_q | cmp_i, so
// the decision of this latch cycle counts even with LATCH_CYCLES = 1.
//
// Packed per-row buses: row r occupies bits [r*W +: W] of a bus with W bits per row.
`timescale 1ns / 1ps  // must match the SystemC time resolution (1 ps, the SystemC default)

module ls_conventional_readout #(
    parameter int ROWS          = 365,  // rows read out in parallel
    parameter int COLUMNS       = 375,  // pixels per row
    parameter int ADDRESS_BITS  = 9,    // width of a streamed column address
    parameter int SAMPLINGS     = 4,    // N
    parameter int RESET_CYCLES  = 4,
    parameter int LATCH_CYCLES  = 1,
    parameter int SEARCH_CYCLES = 2,
    parameter int OUTPUT_CYCLES = 12,
    parameter int FRAME_BITS    = 32,
    // Derived widths (do not override), as in centre_processor / multisampling_sequencer.
    parameter int SamplingBits  = $clog2(SAMPLINGS + 1),
    parameter int CountBits     = $clog2(SAMPLINGS + 1),
    parameter int SumBits       = ADDRESS_BITS + 1 + $clog2(SAMPLINGS + 1),
    parameter int CentreBits    = ADDRESS_BITS + 8
) (
    input  logic                       clk,
    input  logic                       rst,             // synchronous, active high
    input  logic [ ROWS*COLUMNS-1:0]   cmp_i,           // comparator decisions, row r at [r*COLUMNS +: COLUMNS]
    output logic [              2:0]   phase_o,         // sequencer phase (see multisampling_sequencer)
    output logic                       pix_reset_o,
    output logic                       latch_o,
    output logic                       search_start_o,
    output logic                       frame_done_o,
    output logic [ SamplingBits-1:0]   sampling_o,
    output logic [   FRAME_BITS-1:0]   frame_o,
    output logic [         ROWS-1:0]   busy_o,          // per row: address search busy
    output logic [         ROWS-1:0]   addr_valid_o,    // per row: address stream
    output logic [         ROWS-1:0]   addr_bit_o,
    output logic [         ROWS-1:0]   centre_valid_o,  // per row: centre processor outputs
    output logic [ROWS*CentreBits-1:0] centre_q_o,
    output logic [   ROWS*SumBits-1:0] sum_o,
    output logic [ ROWS*CountBits-1:0] count_o
);
  multisampling_sequencer #(
      .SAMPLINGS(SAMPLINGS),
      .RESET_CYCLES(RESET_CYCLES),
      .LATCH_CYCLES(LATCH_CYCLES),
      .SEARCH_CYCLES(SEARCH_CYCLES),
      .ADDRESS_BITS(ADDRESS_BITS),
      .OUTPUT_CYCLES(OUTPUT_CYCLES),
      .FRAME_BITS(FRAME_BITS)
  ) u_sequencer (
      .clk,
      .rst,
      .phase_o,
      .pix_reset_o,
      .latch_o,
      .search_start_o,
      .frame_done_o,
      .sampling_o,
      .frame_o
  );

  for (genvar r = 0; r < ROWS; r++) begin : g_row
    logic [COLUMNS-1:0] act_q;  // comparator latches of the row
    wire  [COLUMNS-1:0] cmp_row = cmp_i[r*COLUMNS+:COLUMNS];
    wire                done;  // unused: the sequencer's schedule already knows when rows finish
    wire                found;  // unused: the centre processor counts only streamed samplings

    always_ff @(posedge clk) begin
      if (rst || pix_reset_o) act_q <= '0;
      else if (latch_o) act_q <= act_q | cmp_row;
    end

    address_search #(
        .COLUMNS(COLUMNS),
        .ADDRESS_BITS(ADDRESS_BITS),
        .SEARCH_CYCLES(SEARCH_CYCLES)
    ) u_search (
        .clk,
        .rst,
        .start_i(search_start_o),
        .act_i(act_q | cmp_row),
        .busy_o(busy_o[r]),
        .found_o(found),
        .addr_valid_o(addr_valid_o[r]),
        .addr_bit_o(addr_bit_o[r]),
        .done_o(done)
    );

    centre_processor #(
        .ADDRESS_BITS(ADDRESS_BITS),
        .SAMPLINGS(SAMPLINGS)
    ) u_centre (
        .clk,
        .rst,
        .clear_i(pix_reset_o),
        .addr_valid_i(addr_valid_o[r]),
        .addr_bit_i(addr_bit_o[r]),
        .valid_o(centre_valid_o[r]),
        .centre_q_o(centre_q_o[r*CentreBits+:CentreBits]),
        .sum_o(sum_o[r*SumBits+:SumBits]),
        .count_o(count_o[r*CountBits+:CountBits])
    );
  end

  // ---- Protocol assertions across rows (simulation only) ----
`ifndef SYNTHESIS
  // One address stream at a time per row, and only in the stream phase; every row's search has
  // finished when the frame access ends (no stream spills into the next frame's reset).
  wire stream_outside = (|addr_valid_o) && (phase_o != 3'd3);
  wire busy_at_end = frame_done_o && (|busy_o);
  always @(posedge clk) begin
    if (!rst) begin
`ifdef __ICARUS__
      if (stream_outside) $error("a_stream_in_stream_phase: address stream outside the stream phase");
      if (busy_at_end) $error("a_rows_idle_at_frame_end: a row search busy at frame_done");
`else
      a_stream_in_stream_phase : assert (!stream_outside)
      else $error("address stream outside the stream phase");
      a_rows_idle_at_frame_end : assert (!busy_at_end)
      else $error("a row search busy at frame_done");
`endif
    end
  end
`endif
endmodule
