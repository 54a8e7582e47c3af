// Frame sequencer of tof-spad with one TDC group (tdc + tdc_histogram; the groups of a row are
// identical and run in parallel). For each of rows_i rows: "laser_cycles" phase, L = 
// laser_cycles_i laser periods of Np = phase_bins_i cycles with the TDC enabled, then
// "histogram_readout", CPT x codes_i words of cycles_per_word_i cycles (read-and-clear).
// Reference: golden/tof_spad/frame_timing.cpp (rows x (L Np + CPT Nc W) cycles) and
// systemc/tof_spad/sensor_kernel.h (its schedule counters); the TDC and histogram against
// TdcGroupKernel / GroupHistogram (tb/tof_spad/cosim.cpp).
//
// Timing: start_i at a rising edge -> the next cycle is the first bin of row 0; the rows follow
// each other without gaps. phase_o: 0 idle, 1 laser_cycles, 2 histogram_readout. start_i is
// only accepted once the histogram has cleared its memory after reset (ready_o).
module tof_spad_sequencer #(
    parameter int CPT        = 4,
    parameter int COL_BITS   = 2,
    parameter int BIN_BITS   = 11,
    parameter int CODES_MAX  = 1024,
    parameter int FINE_BITS  = 16,
    parameter int CORR_BITS  = 3,
    parameter int COUNT_BITS = 16,
    parameter int ROW_BITS   = 8,
    parameter int LASER_BITS = 24
) (
    input  logic                     clk,
    input  logic                     rst,
    input  logic                     start_i,
    input  logic [     ROW_BITS-1:0] rows_i,             // >= 1
    input  logic [   LASER_BITS-1:0] laser_cycles_i,     // L >= 1
    input  logic [     BIN_BITS-1:0] phase_bins_i,       // Np
    input  logic [     BIN_BITS-1:0] codes_i,            // Nc <= Np, <= CODES_MAX
    input  logic [     BIN_BITS-1:0] block_event_i,
    input  logic [     BIN_BITS-1:0] block_overflow_i,
    input  logic [              7:0] cycles_per_word_i,  // W >= 1
    input  logic [          CPT-1:0] hit_i,
    input  logic [CPT*FINE_BITS-1:0] fine_i,
    input  logic [CPT*CORR_BITS-1:0] corr_i,
    output logic                     ready_o,            // idle with a cleared histogram
    output logic [              1:0] phase_o,
    output logic [     ROW_BITS-1:0] row_o,
    output logic                     tdc_event_o,
    output logic                     tdc_overflow_o,
    output logic [     BIN_BITS-1:0] tdc_code_o,
    output logic [          CPT-1:0] tdc_grant_o,
    output logic [              2:0] tdc_lost_o,
    output logic                     word_valid_o,
    output logic [     COL_BITS-1:0] word_column_o,
    output logic [     BIN_BITS-1:0] word_code_o,
    output logic [   COUNT_BITS-1:0] word_o,
    output logic                     peak_valid_o,
    output logic [     COL_BITS-1:0] peak_column_o,
    output logic [     BIN_BITS-1:0] peak_code_o,
    output logic [   COUNT_BITS-1:0] peak_count_o,
    output logic [             39:0] centroid_num_o,
    output logic [             31:0] centroid_den_o,
    output logic                     saturated_o
);
  typedef enum logic [1:0] {
    S_IDLE,
    S_INTEG,
    S_READ
  } state_t;
  state_t state_q;
  logic [ROW_BITS-1:0] row_q;
  logic [LASER_BITS-1:0] laser_q;
  logic [BIN_BITS-1:0] bin_q;
  logic [31:0] read_q;
  logic [BIN_BITS-1:0] t_coarse;
  logic [31:0] t_abs;
  logic t_armed, h_busy;

  wire enable = state_q == S_INTEG;
  wire last_bin = enable && bin_q == phase_bins_i - 1'b1 && laser_q == laser_cycles_i - 1'b1;
  // Readout length CPT x Nc x W (the histogram's own schedule; both end in the same cycle).
  wire [31:0] read_len = 32'(CPT) * 32'(codes_i) * 32'(cycles_per_word_i);
  wire last_read = state_q == S_READ && read_q == read_len - 1;
  wire last_row = row_q == rows_i - 1'b1;

  logic [COL_BITS-1:0] grant_col;
  always_comb begin
    grant_col = '0;
    for (int i = 0; i < CPT; i++) if (tdc_grant_o[i]) grant_col = COL_BITS'(i);
  end

  tdc #(
      .CPT(CPT),
      .BIN_BITS(BIN_BITS),
      .FINE_BITS(FINE_BITS),
      .CORR_BITS(CORR_BITS),
      .ABS_BITS(32)
  ) u_tdc (
      .clk,
      .rst,
      .enable_i(enable),
      .phase_bins_i,
      .codes_i,
      .block_event_i,
      .block_overflow_i,
      .hit_i,
      .fine_i,
      .corr_i,
      .coarse_o(t_coarse),
      .abs_o(t_abs),
      .armed_o(t_armed),
      .grant_o(tdc_grant_o),
      .event_o(tdc_event_o),
      .overflow_o(tdc_overflow_o),
      .code_o(tdc_code_o),
      .lost_o(tdc_lost_o)
  );

  tdc_histogram #(
      .CPT(CPT),
      .COL_BITS(COL_BITS),
      .BIN_BITS(BIN_BITS),
      .CODES_MAX(CODES_MAX),
      .COUNT_BITS(COUNT_BITS),
      .SUM_BITS(40)
  ) u_hist (
      .clk,
      .rst,
      .event_i(tdc_event_o),
      .event_column_i(grant_col),
      .event_code_i(tdc_code_o),
      .read_i(last_bin),
      .codes_i,
      .cycles_per_word_i,
      .busy_o(h_busy),
      .word_valid_o,
      .word_column_o,
      .word_code_o,
      .word_o,
      .peak_valid_o,
      .peak_column_o,
      .peak_code_o,
      .peak_count_o,
      .centroid_num_o,
      .centroid_den_o,
      .saturated_o
  );

  always_ff @(posedge clk) begin
    if (rst) begin
      state_q <= S_IDLE;
      row_q <= '0;
      laser_q <= '0;
      bin_q <= '0;
      read_q <= '0;
    end else begin
      case (state_q)
        S_IDLE: begin
          row_q <= '0;
          laser_q <= '0;
          bin_q <= '0;
          if (start_i && !h_busy) state_q <= S_INTEG;
        end
        S_INTEG: begin
          read_q <= '0;
          if (bin_q == phase_bins_i - 1'b1) begin
            bin_q <= '0;
            laser_q <= laser_q + 1'b1;
          end else bin_q <= bin_q + 1'b1;
          if (last_bin) state_q <= S_READ;
        end
        default: begin  // S_READ
          read_q <= read_q + 1;
          laser_q <= '0;
          if (last_read) begin
            row_q <= last_row ? '0 : row_q + 1'b1;
            state_q <= last_row ? S_IDLE : S_INTEG;
          end
        end
      endcase
    end
  end

  assign ready_o = state_q == S_IDLE && !h_busy;
  assign phase_o = state_q == S_INTEG ? 2'd1 : state_q == S_READ ? 2'd2 : 2'd0;
  assign row_o = row_q;

  wire unused_ok = &{1'b0, t_abs, t_armed};

  always @(posedge clk) begin
    if (!rst) begin
`ifdef __ICARUS__
      if (enable && t_coarse != bin_q) $error("a_coarse_in_step: TDC coarse counter out of step");
      if (enable && h_busy) $error("a_hist_idle_in_integration: histogram busy while integrating");
      if (state_q == S_READ && !h_busy) $error("a_hist_reading: histogram idle during readout");
`else
      a_coarse_in_step : assert (!(enable && t_coarse != bin_q))
      else $error("TDC coarse counter out of step with the sequencer");
      a_hist_idle_in_integration : assert (!(enable && h_busy))
      else $error("histogram busy while integrating (events would be lost)");
      a_hist_reading : assert (!(state_q == S_READ && !h_busy))
      else $error("histogram idle during the readout phase");
`endif
    end
  end
endmodule
