// Frame sequencer of tof-lockin: per frame, N_acc gate periods (lockin_gate_generator), then
// row by row one column-parallel ADC conversion (adc_start_o) and the row's output shift;
// `frames_i` frames back to back (LED frame, ambient frame alternate when ambient_i is set).
// Reference: systemc/tof_lockin/sensor_kernel.h, TofLockinSensorKernel in tick mode
// (event_skipping = false, one step = one cycle; gate and readout cycles on one clock here)
// and golden/tof_lockin/frame_timing.cpp. phase_o uses LockinPhase: 0 idle, 1-3 PHASE1-3,
// 4 adc_conversion, 5 output.
//
// Timing: start_i at a rising edge -> the next cycle is PHASE1 cycle 0 of frame 0; the first
// PHASE1 cycle of a frame follows the last output cycle of the previous one directly.
module tof_lockin_sequencer #(
    parameter int CYCLE_BITS = 16,  // T0, T_rep, conversion and output cycle counters
    parameter int ACC_BITS   = 20,  // accumulations per frame
    parameter int ROW_BITS   = 12,  // rows
    parameter int FRAME_BITS = 16   // frames per run
) (
    input  logic                  clk,
    input  logic                  rst,
    input  logic                  start_i,
    input  logic [CYCLE_BITS-1:0] t0_cycles_i,
    input  logic [CYCLE_BITS-1:0] period_cycles_i,
    input  logic [  ACC_BITS-1:0] accumulations_i,
    input  logic [  ROW_BITS-1:0] rows_i,               // >= 1
    input  logic [CYCLE_BITS-1:0] conversion_cycles_i,  // >= 1
    input  logic [CYCLE_BITS-1:0] output_cycles_i,      // >= 1
    input  logic [FRAME_BITS-1:0] frames_i,             // >= 1
    input  logic                  ambient_i,            // odd frames are ambient (LED off)
    output logic                  busy_o,
    output logic [           2:0] phase_o,
    output logic                  tx1_o,
    output logic                  tx2_o,
    output logic                  txd_o,
    output logic                  light_o,
    output logic                  adc_start_o,          // next cycle is a row's first conversion cycle
    output logic [  ROW_BITS-1:0] row_o,                // row in readout
    output logic [FRAME_BITS-1:0] frame_o,
    output logic                  frame_done_o          // last cycle of a frame
);
  typedef enum logic [1:0] {
    S_IDLE,
    S_GATES,
    S_CONV,
    S_OUT
  } state_t;
  state_t state_q;
  logic [CYCLE_BITS-1:0] cnt_q;
  logic [ROW_BITS-1:0] row_q;
  logic [FRAME_BITS-1:0] frame_q;

  logic g_busy, g_tx1, g_tx2, g_txd, g_light, g_last;
  logic [CYCLE_BITS-1:0] g_cycle;
  logic [ACC_BITS-1:0] g_acc;

  wire last_conv = state_q == S_CONV && cnt_q == conversion_cycles_i - 1'b1;
  wire last_out = state_q == S_OUT && cnt_q == output_cycles_i - 1'b1;
  wire last_row = row_q == rows_i - 1'b1;
  wire frame_end = last_out && last_row;
  wire more_frames = frame_q != frames_i - 1'b1;
  wire gate_start = (state_q == S_IDLE && start_i) || (frame_end && more_frames);

  lockin_gate_generator #(
      .CYCLE_BITS(CYCLE_BITS),
      .ACC_BITS  (ACC_BITS)
  ) u_gates (
      .clk,
      .rst,
      .start_i(gate_start),
      .t0_cycles_i,
      .period_cycles_i,
      .accumulations_i,
      .busy_o(g_busy),
      .tx1_o(g_tx1),
      .tx2_o(g_tx2),
      .txd_o(g_txd),
      .light_o(g_light),
      .last_o(g_last),
      .cycle_o(g_cycle),
      .accumulation_o(g_acc)
  );

  always_ff @(posedge clk) begin
    if (rst) begin
      state_q <= S_IDLE;
      cnt_q <= '0;
      row_q <= '0;
      frame_q <= '0;
    end else begin
      case (state_q)
        S_IDLE: begin
          frame_q <= '0;
          if (start_i) state_q <= S_GATES;
        end
        S_GATES: begin
          cnt_q <= '0;
          row_q <= '0;
          if (g_last) state_q <= S_CONV;
        end
        S_CONV: begin
          cnt_q <= last_conv ? '0 : cnt_q + 1'b1;
          if (last_conv) state_q <= S_OUT;
        end
        default: begin  // S_OUT
          cnt_q <= last_out ? '0 : cnt_q + 1'b1;
          if (last_out) begin
            row_q <= last_row ? '0 : row_q + 1'b1;
            if (!last_row) state_q <= S_CONV;
            else if (more_frames) begin
              state_q <= S_GATES;
              frame_q <= frame_q + 1'b1;
            end else state_q <= S_IDLE;
          end
        end
      endcase
    end
  end

  wire led_on = !(ambient_i && frame_q[0]);

  always_comb begin
    busy_o = state_q != S_IDLE;
    case (state_q)
      S_GATES: phase_o = g_tx1 ? 3'd1 : g_tx2 ? 3'd2 : 3'd3;
      S_CONV:  phase_o = 3'd4;
      S_OUT:   phase_o = 3'd5;
      default: phase_o = 3'd0;
    endcase
    tx1_o = g_tx1;
    tx2_o = g_tx2;
    txd_o = g_txd;
    light_o = g_light && led_on;
    adc_start_o = (state_q == S_GATES && g_last) || (last_out && !last_row);
    row_o = row_q;
    frame_o = frame_q;
    frame_done_o = frame_end;
  end

  // Debug-only views of the generator (kept for waveforms, not ports).
  wire unused_ok = &{1'b0, g_cycle, g_acc};

  always @(posedge clk) begin
    if (!rst) begin
`ifdef __ICARUS__
      if ((state_q == S_GATES) != g_busy) $error("a_gates_in_gate_phase: gate generator out of step");
      if (state_q != S_IDLE && state_q != S_GATES && row_q >= rows_i) $error("a_row_in_range: row counter past rows");
`else
      a_gates_in_gate_phase : assert ((state_q == S_GATES) == g_busy)
      else $error("gate generator busy outside the gate phase (or idle inside it)");
      a_row_in_range : assert (state_q == S_IDLE || state_q == S_GATES || row_q < rows_i)
      else $error("row counter past rows (would wrap silently)");
`endif
    end
  end
endmodule
