// Column TDC of tof-spad, shared by CPT pixel columns, with first-hit arbitration, dead time and
// overflow. Reference: systemc/tof_spad/tdc_kernel.h, TdcGroupKernel (the per-hit form of the
// TDC in TofSpadKernel::simulate_group; cycle-exact to this file).
//
// Clock: one cycle per nominal LSB. While enable_i is high the coarse counter runs through the
// Np = phase_bins_i cycles of each laser period (it restarts at every START, so START is the
// coarse wrap) and abs_o counts bins since the integration began. A pixel hit arrives in the
// cycle that contains it with two interpolator values:
//   fine_i  its position inside the cycle (FINE_BITS, for arbitration: earliest wins, then the
//           lowest column),
//   corr_i  the bin correction of the interpolator against the TDC's actual (INL/DNL) edges:
//           code = coarse + corr (signed CORR_BITS).
// A hit is eligible when its bin (abs + corr) is not before armed_from. The winner is recorded:
// code < codes_i -> event_o, else overflow_o (no histogram event); the TDC then stays stopped
// until max(bin + block bins, next START). Every other hit of the cycle is lost (lost_o).
module tdc #(
    parameter int CPT       = 4,   // pixel columns sharing the TDC
    parameter int BIN_BITS  = 11,  // coarse counter / code width (Np <= 2^BIN_BITS)
    parameter int FINE_BITS = 16,  // interpolator phase width
    parameter int CORR_BITS = 3,   // signed bin correction width
    parameter int ABS_BITS  = 32   // bins since the integration began
) (
    input  logic                     clk,
    input  logic                     rst,                // synchronous, active high
    input  logic                     enable_i,           // row integration (laser cycles) running
    input  logic [     BIN_BITS-1:0] phase_bins_i,       // Np >= 1
    input  logic [     BIN_BITS-1:0] codes_i,            // Nc <= Np
    input  logic [     BIN_BITS-1:0] block_event_i,      // bins stopped after an event
    input  logic [     BIN_BITS-1:0] block_overflow_i,   // bins stopped after an overflow
    input  logic [          CPT-1:0] hit_i,              // avalanche in this cycle, per column
    input  logic [CPT*FINE_BITS-1:0] fine_i,             // column i at [i*FINE_BITS +: FINE_BITS]
    input  logic [CPT*CORR_BITS-1:0] corr_i,             // column i at [i*CORR_BITS +: CORR_BITS]
    output logic [     BIN_BITS-1:0] coarse_o,           // coarse count of this cycle
    output logic [     ABS_BITS-1:0] abs_o,              // bin index since the integration began
    output logic                     armed_o,            // this cycle's bin is armed
    output logic [          CPT-1:0] grant_o,            // one-hot: the recorded hit's column
    output logic                     event_o,            // recorded, code < codes_i
    output logic                     overflow_o,         // recorded, code >= codes_i
    output logic [     BIN_BITS-1:0] code_o,             // code of the recorded hit
    output logic [              2:0] lost_o              // hits of this cycle not recorded
);
  logic [BIN_BITS-1:0] coarse_q;
  logic [ABS_BITS-1:0] abs_q, armed_from_q;

  // Arbitration (combinational): earliest eligible hit, then the lowest column.
  logic signed [ABS_BITS:0] bin_abs[CPT];
  logic [CPT-1:0] eligible, grant;
  logic [FINE_BITS-1:0] best_fine;
  logic [BIN_BITS:0] code_wide;
  logic [ABS_BITS:0] win_abs;
  logic [2:0] hits;
  always_comb begin
    grant = '0;
    best_fine = '1;
    win_abs = '0;
    code_wide = '0;
    hits = '0;
    for (int i = 0; i < CPT; i++) begin
      bin_abs[i] = $signed({1'b0, abs_q}) + ABS_BITS'($signed(corr_i[i*CORR_BITS+:CORR_BITS]));
      eligible[i] = enable_i && hit_i[i] && bin_abs[i] >= $signed({1'b0, armed_from_q});
      hits = hits + {2'b0, hit_i[i] && enable_i};
    end
    for (int i = CPT - 1; i >= 0; i--) begin  // reverse: ties go to the lowest column
      if (eligible[i] && fine_i[i*FINE_BITS+:FINE_BITS] <= best_fine) begin
        best_fine = fine_i[i*FINE_BITS+:FINE_BITS];
        grant = '0;
        grant[i] = 1'b1;
        win_abs = bin_abs[i];
        code_wide = {1'b0, coarse_q} + (BIN_BITS + 1)'($signed(corr_i[i*CORR_BITS+:CORR_BITS]));
      end
    end
  end

  wire recorded = |grant;
  wire is_event = recorded && code_wide < {1'b0, codes_i};
  wire [ABS_BITS:0] rearm = win_abs + (is_event ? {{(ABS_BITS + 1 - BIN_BITS) {1'b0}}, block_event_i}
                                                 : {{(ABS_BITS + 1 - BIN_BITS) {1'b0}}, block_overflow_i});
  wire [ABS_BITS:0] next_start = {1'b0, abs_q} - {{(ABS_BITS + 1 - BIN_BITS) {1'b0}}, coarse_q} +
                                 {{(ABS_BITS + 1 - BIN_BITS) {1'b0}}, phase_bins_i};
  wire last_coarse = coarse_q == phase_bins_i - 1'b1;

  always_ff @(posedge clk) begin
    if (rst || !enable_i) begin
      coarse_q <= '0;
      abs_q <= '0;
      armed_from_q <= '0;
    end else begin
      coarse_q <= last_coarse ? '0 : coarse_q + 1'b1;
      abs_q <= abs_q + 1'b1;
      if (recorded) armed_from_q <= ABS_BITS'(rearm > next_start ? rearm : next_start);
    end
  end

  assign coarse_o = coarse_q;
  assign abs_o = abs_q;
  assign armed_o = enable_i && abs_q >= armed_from_q;
  assign grant_o = grant;
  assign event_o = is_event;
  assign overflow_o = recorded && !is_event;
  assign code_o = code_wide[BIN_BITS-1:0];
  assign lost_o = hits - {2'b0, recorded};

  always @(posedge clk) begin
    if (!rst && enable_i) begin
`ifdef __ICARUS__
      if ((grant & (grant - 1'b1)) != 0) $error("a_one_grant: more than one column granted");
      if (coarse_q >= phase_bins_i) $error("a_coarse_in_period: coarse counter past Np");
      if (&abs_q) $error("a_abs_no_wrap: bin counter would wrap");
      if (recorded && code_wide[BIN_BITS]) $error("a_code_in_range: code below 0 or too wide");
`else
      a_one_grant : assert ((grant & (grant - 1'b1)) == 0)
      else $error("more than one column granted");
      a_coarse_in_period : assert (coarse_q < phase_bins_i)
      else $error("coarse counter past Np (would wrap silently)");
      a_abs_no_wrap : assert (!(&abs_q))
      else $error("bin counter would wrap silently");
      a_code_in_range : assert (!(recorded && code_wide[BIN_BITS]))
      else $error("corrected code below 0 or past the code width");
`endif
    end
  end
endmodule
