// Lock-in gate timing generator of tof-lockin: PHASE1 (TX1), PHASE2 (TX2), PHASE3 (TXD) and the
// light pulse, for `accumulations_i` repetition periods after one `start_i`.
// Reference: systemc/tof_lockin/lockin_gate_generator_kernel.h, LockinGateGeneratorKernel (cycle-exact to this file):
// in cycle k of a period, tx1 = k < T0, tx2 = T0 <= k < 2 T0, txd = k >= 2 T0, light = tx1;
// the period is T_rep = T0 / duty cycles (`period_cycles_i`, >= 2 T0).
//
// Timing: start_i sampled at a rising edge -> the next cycle is cycle 0 of PHASE1 of
// accumulation 0. Every output is a register or a function of registers (stable all cycle).
// last_o marks the final gate cycle of the frame so a sequencer can follow without a gap.
// Parameters are runtime inputs (held constant while busy) so one instance covers the preset
// ranges; the widths are parameters.
module lockin_gate_generator #(
    parameter int CYCLE_BITS = 16,  // width of T0 / T_rep in gate-clock cycles
    parameter int ACC_BITS   = 20   // width of the accumulation count
) (
    input  logic                  clk,
    input  logic                  rst,               // synchronous, active high
    input  logic                  start_i,           // begin N_acc periods (ignored while busy)
    input  logic [CYCLE_BITS-1:0] t0_cycles_i,       // T0 >= 1
    input  logic [CYCLE_BITS-1:0] period_cycles_i,   // T_rep >= 2 T0
    input  logic [  ACC_BITS-1:0] accumulations_i,   // N_acc >= 1
    output logic                  busy_o,            // periods in progress
    output logic                  tx1_o,             // PHASE1: photogate -> FD1
    output logic                  tx2_o,             // PHASE2: photogate -> FD2
    output logic                  txd_o,             // PHASE3: photogate -> drain
    output logic                  light_o,           // LED pulse, [0, T0) of every period
    output logic                  last_o,            // last gate cycle of the last period
    output logic [CYCLE_BITS-1:0] cycle_o,           // cycle within the period
    output logic [  ACC_BITS-1:0] accumulation_o     // current period
);
  logic [CYCLE_BITS-1:0] cyc_q;
  logic [ACC_BITS-1:0] acc_q;
  logic busy_q;

  wire end_of_period = cyc_q == period_cycles_i - 1'b1;
  wire last_period = acc_q == accumulations_i - 1'b1;

  always_ff @(posedge clk) begin
    if (rst) begin
      busy_q <= 1'b0;
      cyc_q <= '0;
      acc_q <= '0;
    end else if (!busy_q) begin
      busy_q <= start_i;
      cyc_q <= '0;
      acc_q <= '0;
    end else if (end_of_period) begin
      cyc_q <= '0;
      acc_q <= acc_q + 1'b1;
      busy_q <= !last_period;
    end else begin
      cyc_q <= cyc_q + 1'b1;
    end
  end

  always_comb begin
    busy_o = busy_q;
    tx1_o = busy_q && cyc_q < t0_cycles_i;
    tx2_o = busy_q && cyc_q >= t0_cycles_i && {1'b0, cyc_q} < {t0_cycles_i, 1'b0};
    txd_o = busy_q && {1'b0, cyc_q} >= {t0_cycles_i, 1'b0};
    light_o = tx1_o;
    last_o = busy_q && end_of_period && last_period;
    cycle_o = cyc_q;
    accumulation_o = acc_q;
  end

  // ---- Assertions (simulation only); Icarus 11 rejects labelled immediate assertions ----
  always @(posedge clk) begin
    if (!rst && busy_q) begin
`ifdef __ICARUS__
      if ((tx1_o + tx2_o + txd_o) != 1) $error("a_gates_exclusive: TX1/TX2/TXD overlap or gap");
      if (cyc_q >= period_cycles_i) $error("a_cycle_in_period: cycle counter past T_rep");
      if (acc_q >= accumulations_i) $error("a_acc_in_range: accumulation counter past N_acc");
`else
      a_gates_exclusive : assert ((tx1_o + tx2_o + txd_o) == 1)
      else $error("TX1/TX2/TXD overlap or gap");
      a_cycle_in_period : assert (cyc_q < period_cycles_i)
      else $error("cycle counter past T_rep (would wrap silently)");
      a_acc_in_range : assert (acc_q < accumulations_i)
      else $error("accumulation counter past N_acc (would wrap silently)");
`endif
    end
  end
endmodule
