// Icarus replay of a Verilator co-simulation run of rtl/tof_lockin/lockin_gate_generator.sv (ctest label
// iverilog): reads the per-cycle inputs and the outputs Verilator produced, recorded by
// run_lockin_gate_generator_cosim(..., record_path), drives the same inputs into the same RTL
// and requires identical outputs in every cycle after reset. +record=<file>. Prints PASS.
`timescale 1ns / 1ps

module lockin_gate_generator_replay_tb;
  logic clk = 1'b0, rst = 1'b1, start = 1'b0;
  logic [15:0] t0 = 16'd1, period = 16'd2;
  logic [19:0] acc = 20'd1;
  logic busy, tx1, tx2, txd, light, last;
  logic [15:0] cycle;
  logic [19:0] accumulation;

  lockin_gate_generator #(
      .CYCLE_BITS(16),
      .ACC_BITS  (20)
  ) dut (
      .clk,
      .rst,
      .start_i(start),
      .t0_cycles_i(t0),
      .period_cycles_i(period),
      .accumulations_i(acc),
      .busy_o(busy),
      .tx1_o(tx1),
      .tx2_o(tx2),
      .txd_o(txd),
      .light_o(light),
      .last_o(last),
      .cycle_o(cycle),
      .accumulation_o(accumulation)
  );

  always #5 clk = ~clk;

  integer fd, n, lines = 0, errors = 0, r_rst, r_start, r_t0, r_period, r_acc;
  reg [5:0] want;
  reg [1023:0] path;

  initial begin
    if (!$value$plusargs("record=%s", path)) $fatal(1, "FAIL: no +record=<file>");
    fd = $fopen(path, "r");
    if (fd == 0) $fatal(1, "FAIL: cannot open the record");
    n = $fscanf(fd, "%d %d %d %d %d %b\n", r_rst, r_start, r_t0, r_period, r_acc, want);
    while (n == 6) begin
      // Inputs of this cycle, applied just after its rising edge (as the SystemC stimulus).
      #1;
      rst = r_rst[0];
      start = r_start[0];
      t0 = r_t0[15:0];
      period = r_period[15:0];
      acc = r_acc[19:0];
      @(negedge clk);
      if (lines >= 3 && {busy, tx1, tx2, txd, light, last} !== want) begin
        errors = errors + 1;
        if (errors <= 10)
          $display("cycle %0d: busy,tx1,tx2,txd,light,last Verilator %b Icarus %b", lines, want,
                   {busy, tx1, tx2, txd, light, last});
      end
      lines = lines + 1;
      @(posedge clk);
      n = $fscanf(fd, "%d %d %d %d %d %b\n", r_rst, r_start, r_t0, r_period, r_acc, want);
    end
    $fclose(fd);
    if (lines < 100) $fatal(1, "FAIL: record too short (%0d cycles)", lines);
    if (errors != 0) $fatal(1, "FAIL: %0d of %0d cycles differ", errors, lines);
    $display("PASS: %0d cycles replayed, outputs identical to Verilator from cycle 3 on", lines);
    $finish;
  end
endmodule
