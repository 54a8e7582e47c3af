// Frame sequencer of ls-demodulation with the row readout through the chained address search
// (address_search.sv, shared over the rows). Per frame, for each of the K = detections_i
// decisions: "integration" W = window_cycles_i cycles (integ_reset_o in the first: the
// integrators reset at its edge), "decision" 1 cycle (latch_o: every comparator latches), then
// "row_readout": rows_i rows of ROW_CYCLES = 1 + SEARCH_CYCLES + 2 ADDRESS_BITS cycles, each
// starting the search on that row's comparator outputs (act_i, row_o) in its first cycle.
// row_valid_o pulses in the cycle after a row's search ends, with found_o and the left / right
// addresses deserialised from the stream. frames_i frames back to back.
// Reference: systemc/ls_demodulation/sensor_kernel.h (DemodSensorKernel ticking, whose
// readout_row_cycles sets S = row_cycles - 1 - 2B) and golden/ls_demodulation/frame_timing.cpp.
// phase_o follows DemodPhase: 0 integration, 1 decision, 2 row readout, 3 idle (Done).
`timescale 1ns / 1ps
module ls_demodulation_sequencer #(
    parameter int COLUMNS       = 120,
    parameter int ADDRESS_BITS  = 7,
    parameter int SEARCH_CYCLES = 26,
    parameter int CYCLE_BITS    = 16,
    parameter int ROW_BITS      = 8,
    parameter int K_BITS        = 8,
    parameter int FRAME_BITS    = 16
) (
    input  logic                    clk,
    input  logic                    rst,
    input  logic                    start_i,
    input  logic [  CYCLE_BITS-1:0] window_cycles_i,  // W >= 1
    input  logic [      K_BITS-1:0] detections_i,     // K >= 1
    input  logic [    ROW_BITS-1:0] rows_i,           // >= 1
    input  logic [  FRAME_BITS-1:0] frames_i,         // >= 1
    input  logic [     COLUMNS-1:0] act_i,            // comparator outputs of row row_o
    output logic                    busy_o,
    output logic [             1:0] phase_o,
    output logic                    integ_reset_o,
    output logic                    latch_o,
    output logic [    ROW_BITS-1:0] row_o,
    output logic [      K_BITS-1:0] decision_o,
    output logic [  FRAME_BITS-1:0] frame_o,
    output logic                    search_start_o,
    output logic                    addr_valid_o,
    output logic                    addr_bit_o,
    output logic                    row_valid_o,
    output logic                    found_o,
    output logic [ADDRESS_BITS-1:0] left_o,
    output logic [ADDRESS_BITS-1:0] right_o
);
  localparam int ROW_CYCLES = 1 + SEARCH_CYCLES + 2 * ADDRESS_BITS;

  typedef enum logic [1:0] {
    S_INTEG = 2'd0,
    S_DECIDE = 2'd1,
    S_READ = 2'd2,
    S_IDLE = 2'd3
  } state_t;
  state_t state_q;
  logic [CYCLE_BITS-1:0] cnt_q;
  logic [ROW_BITS-1:0] row_q;
  logic [K_BITS-1:0] dec_q;
  logic [FRAME_BITS-1:0] frame_q;
  logic [2*ADDRESS_BITS-1:0] bits_q;
  logic valid_q, found_q;

  logic s_busy, s_found, s_valid, s_bit, s_done;
  wire s_start = state_q == S_READ && cnt_q == '0;

  address_search #(
      .COLUMNS(COLUMNS),
      .ADDRESS_BITS(ADDRESS_BITS),
      .SEARCH_CYCLES(SEARCH_CYCLES)
  ) u_search (
      .clk,
      .rst,
      .start_i(s_start),
      .act_i,
      .busy_o(s_busy),
      .found_o(s_found),
      .addr_valid_o(s_valid),
      .addr_bit_o(s_bit),
      .done_o(s_done)
  );

  wire last_integ = cnt_q == window_cycles_i - 1'b1;
  wire last_in_row = cnt_q == CYCLE_BITS'(ROW_CYCLES - 1);
  wire last_row = row_q == rows_i - 1'b1;
  wire last_dec = dec_q == detections_i - 1'b1;
  wire last_frame = frame_q == frames_i - 1'b1;

  always_ff @(posedge clk) begin
    if (rst) begin
      state_q <= S_IDLE;
      cnt_q <= '0;
      row_q <= '0;
      dec_q <= '0;
      frame_q <= '0;
      bits_q <= '0;
      valid_q <= 1'b0;
      found_q <= 1'b0;
    end else begin
      valid_q <= s_done;
      if (s_done) found_q <= s_found;
      if (s_start) bits_q <= '0;
      else if (s_valid) bits_q <= {bits_q[2*ADDRESS_BITS-2:0], s_bit};
      case (state_q)
        S_IDLE: begin
          cnt_q <= '0;
          row_q <= '0;
          dec_q <= '0;
          frame_q <= '0;
          if (start_i) state_q <= S_INTEG;
        end
        S_INTEG: begin
          cnt_q <= last_integ ? '0 : cnt_q + 1'b1;
          if (last_integ) state_q <= S_DECIDE;
        end
        S_DECIDE: begin
          cnt_q <= '0;
          row_q <= '0;
          state_q <= S_READ;
        end
        default: begin  // S_READ
          cnt_q <= last_in_row ? '0 : cnt_q + 1'b1;
          if (last_in_row) begin
            row_q <= last_row ? '0 : row_q + 1'b1;
            if (last_row) begin
              if (!last_dec) begin
                dec_q <= dec_q + 1'b1;
                state_q <= S_INTEG;
              end else if (!last_frame) begin
                dec_q <= '0;
                frame_q <= frame_q + 1'b1;
                state_q <= S_INTEG;
              end else begin
                state_q <= S_IDLE;
              end
            end
          end
        end
      endcase
    end
  end

  assign busy_o = state_q != S_IDLE;
  assign phase_o = state_q;
  assign integ_reset_o = state_q == S_INTEG && cnt_q == '0;
  assign latch_o = state_q == S_DECIDE;
  assign row_o = row_q;
  assign decision_o = dec_q;
  assign frame_o = frame_q;
  assign search_start_o = s_start;
  assign addr_valid_o = s_valid;
  assign addr_bit_o = s_bit;
  assign row_valid_o = valid_q;
  assign found_o = found_q;
  assign left_o = bits_q[2*ADDRESS_BITS-1:ADDRESS_BITS];
  assign right_o = bits_q[ADDRESS_BITS-1:0];

  wire unused_ok = &{1'b0, s_busy};

  always @(posedge clk) begin
    if (!rst) begin
`ifdef __ICARUS__
      if (state_q == S_READ && cnt_q >= CYCLE_BITS'(ROW_CYCLES)) $error("a_row_cycle_in_range: row counter past ROW_CYCLES");
      if (s_done && state_q != S_READ) $error("a_search_in_readout: search ended outside the row readout");
`else
      a_row_cycle_in_range : assert (!(state_q == S_READ && cnt_q >= CYCLE_BITS'(ROW_CYCLES)))
      else $error("row cycle counter past ROW_CYCLES (would wrap silently)");
      a_search_in_readout : assert (!(s_done && state_q != S_READ))
      else $error("address search ended outside the row readout");
`endif
    end
  end
endmodule
