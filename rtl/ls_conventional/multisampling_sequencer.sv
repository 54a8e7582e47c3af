// multisampling_sequencer: the frame sequencer of ls-conventional (thesis [31]), one per array.
// It times one frame access with N samplings during the integration: the pixel reset, a
// comparator latch strobe per sampling (the comparators decide at t_k = k T / N and the pixels
// keep the decision), the search start of every row in the last latch cycle, the address-stream
// phase of the rows, and the output phase. Views of the same block:
// systemc/ls_conventional/multisampling_sequencer_kernel.h (cycle kernel, whose header comment is this schedule; this
// file is cycle-exact to it) and systemc/ls_conventional/multisampling_sequencer.h (sc_module).
//
// Cycle c of a frame access (P = LATCH + SEARCH + 2 ADDRESS_BITS, F = RESET + N P + OUTPUT):
//   [0, RESET)                       phase 0 reset    pix_reset_o
//   sampling k = 1..N at base = RESET + (k-1) P:
//     [base, base + LATCH)           phase 1 latch    latch_o, sampling_o = k;
//                                                     search_start_o in the last latch cycle
//     [base + LATCH, + SEARCH)       phase 2 search   sampling_o = k
//     [.., base + P)                 phase 3 stream   sampling_o = k
//   [RESET + N P, F)                 phase 4 output   frame_done_o in the last cycle
// Frame accesses follow back to back; frame_o counts them. Outputs are decoded from registers.
// Reset is synchronous and active high and holds cycle 0 of frame 0.
`timescale 1ns / 1ps  // must match the SystemC time resolution (1 ps, the SystemC default)

module multisampling_sequencer #(
    parameter int SAMPLINGS     = 4,   // N, samplings per integration
    parameter int RESET_CYCLES  = 4,   // FrameTimingConfig::reset_cycles
    parameter int LATCH_CYCLES  = 1,   // FrameTimingConfig::latch_cycles
    parameter int SEARCH_CYCLES = 2,   // FrameTimingConfig::search_cycles
    parameter int ADDRESS_BITS  = 9,   // FrameTimingConfig::address_bits (two addresses stream)
    parameter int OUTPUT_CYCLES = 12,  // FrameTimingConfig::output_cycles
    parameter int FRAME_BITS    = 32,  // frame-access counter width
    // Derived width (do not override).
    parameter int SamplingBits  = $clog2(SAMPLINGS + 1)
) (
    input  logic                    clk,
    input  logic                    rst,             // synchronous, active high
    output logic [             2:0] phase_o,         // 0 reset, 1 latch, 2 search, 3 stream, 4 output
    output logic                    pix_reset_o,     // reset phase
    output logic                    latch_o,         // comparator latch (latch phase)
    output logic                    search_start_o,  // last latch cycle: start of every row's search
    output logic                    frame_done_o,    // last cycle of the frame access
    output logic [SamplingBits-1:0] sampling_o,      // k during latch/search/stream, else 0
    output logic [  FRAME_BITS-1:0] frame_o          // frame-access counter
);
  localparam int StreamCycles = 2 * ADDRESS_BITS;
  localparam int MaxPhase = (RESET_CYCLES > OUTPUT_CYCLES ? RESET_CYCLES : OUTPUT_CYCLES) +
                            LATCH_CYCLES + SEARCH_CYCLES + StreamCycles;
  localparam int CountBits = $clog2(MaxPhase + 1);

  typedef enum logic [2:0] {
    RESET  = 3'd0,
    LATCH  = 3'd1,
    SEARCH = 3'd2,
    STREAM = 3'd3,
    OUTPUT = 3'd4
  } phase_e;

  phase_e                    phase_q;
  logic   [   CountBits-1:0] count_q;  // cycles spent in the current phase
  logic   [SamplingBits-1:0] sampling_q;  // k, 0 outside the samplings
  logic   [  FRAME_BITS-1:0] frame_q;

  // Last cycle of each phase.
  wire reset_last  = (phase_q == RESET) && (count_q == CountBits'(RESET_CYCLES - 1));
  wire latch_last  = (phase_q == LATCH) && (count_q == CountBits'(LATCH_CYCLES - 1));
  wire search_last = (phase_q == SEARCH) && (count_q == CountBits'(SEARCH_CYCLES - 1));
  wire stream_last = (phase_q == STREAM) && (count_q == CountBits'(StreamCycles - 1));
  wire output_last = (phase_q == OUTPUT) && (count_q == CountBits'(OUTPUT_CYCLES - 1));
  wire last_sampling = (sampling_q == SamplingBits'(SAMPLINGS));

  always_ff @(posedge clk) begin
    if (rst) begin
      phase_q    <= RESET;
      count_q    <= '0;
      sampling_q <= '0;
      frame_q    <= '0;
    end else begin
      count_q <= count_q + 1'b1;
      if (reset_last || latch_last || search_last || stream_last || output_last) count_q <= '0;
      case (phase_q)
        RESET:
        if (reset_last) begin
          phase_q    <= LATCH;
          sampling_q <= SamplingBits'(1);
        end
        LATCH:  if (latch_last) phase_q <= SEARCH;
        SEARCH: if (search_last) phase_q <= STREAM;
        STREAM:
        if (stream_last) begin
          phase_q    <= last_sampling ? OUTPUT : LATCH;
          sampling_q <= last_sampling ? '0 : sampling_q + 1'b1;
        end
        OUTPUT:
        if (output_last) begin
          phase_q <= RESET;
          frame_q <= frame_q + 1'b1;
        end
        default: phase_q <= RESET;
      endcase
    end
  end

  assign phase_o        = phase_q;
  assign pix_reset_o    = (phase_q == RESET);
  assign latch_o        = (phase_q == LATCH);
  assign search_start_o = latch_last;
  assign frame_done_o   = output_last;
  assign sampling_o     = sampling_q;
  assign frame_o        = frame_q;

  // ---- Parameter checks and assertions (simulation only) ----
`ifndef SYNTHESIS
  if (SAMPLINGS < 1 || RESET_CYCLES < 1 || LATCH_CYCLES < 1 || SEARCH_CYCLES < 1 ||
      ADDRESS_BITS < 1 || OUTPUT_CYCLES < 1 || FRAME_BITS < 1)
  begin : g_bad_parameters
`ifdef VERILATOR
    $error("multisampling_sequencer: every cycle count and SAMPLINGS must be >= 1");
`else
    initial $fatal(1, "multisampling_sequencer: every cycle count and SAMPLINGS must be >= 1");
`endif
  end

  wire frame_wraps = output_last && (frame_q == '1);
  // With SAMPLINGS = 2^k - 1 the index field cannot exceed SAMPLINGS: the comparison would be
  // constant (Verilator CMPCONST, fatal), so it exists only where an index can be out of range.
  logic sampling_over;
  if ((1 << SamplingBits) - 1 > SAMPLINGS) begin : g_sampling_over
    assign sampling_over = sampling_q > SamplingBits'(SAMPLINGS);
  end else begin : g_sampling_full_range
    assign sampling_over = 1'b0;
  end
  wire sampling_bad = (phase_q == LATCH || phase_q == SEARCH || phase_q == STREAM) &&
                      (sampling_q == '0 || sampling_over);
  always @(posedge clk) begin
    if (!rst) begin
`ifdef __ICARUS__
      if (frame_wraps) $error("a_frame_no_wrap: frame counter wraps");
      if (sampling_bad) $error("a_sampling_in_range: sampling index out of 1..SAMPLINGS");
`else
      a_frame_no_wrap : assert (!frame_wraps)
      else $error("frame counter wraps");
      a_sampling_in_range : assert (!sampling_bad)
      else $error("sampling index out of 1..SAMPLINGS");
`endif
    end
  end
`endif
endmodule
