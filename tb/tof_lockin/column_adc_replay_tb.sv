// Icarus replay of a Verilator co-simulation run of rtl/tof_lockin/column_adc.sv (ctest label iverilog):
// the recorded per-cycle inputs (including the comparator the testbench computed) and the
// outputs Verilator produced; the same RTL under Icarus must give identical outputs in every
// cycle after reset. +record=<file>. Prints PASS.
`timescale 1ns / 1ps

module column_adc_replay_tb;
  logic clk = 1'b0, rst = 1'b1, start = 1'b0, cmp = 1'b0;
  logic [15:0] conv = 16'd4096;
  logic [4:0] bits = 5'd12;
  logic busy, done;
  logic [11:0] ramp, code;

  column_adc #(
      .BITS(12),
      .CYCLE_BITS(16)
  ) dut (
      .clk,
      .rst,
      .start_i(start),
      .conversion_cycles_i(conv),
      .bits_i(bits),
      .cmp_i(cmp),
      .busy_o(busy),
      .ramp_o(ramp),
      .done_o(done),
      .code_o(code)
  );

  always #5 clk = ~clk;

  integer fd, n, lines = 0, errors = 0;
  integer r_rst, r_start, r_conv, r_bits, r_cmp, w_busy, w_ramp, w_done, w_code;
  reg [1023:0] path;

  initial begin
    if (!$value$plusargs("record=%s", path)) $fatal(1, "FAIL: no +record=<file>");
    fd = $fopen(path, "r");
    if (fd == 0) $fatal(1, "FAIL: cannot open the record");
    n = $fscanf(fd, "%d %d %d %d %d %d %d %d %d\n", r_rst, r_start, r_conv, r_bits, r_cmp,
                  w_busy, w_ramp, w_done, w_code);
    while (n == 9) begin
      #1;
      rst = r_rst[0];
      start = r_start[0];
      conv = r_conv[15:0];
      bits = r_bits[4:0];
      @(negedge clk);
      cmp = r_cmp[0];  // the analog comparator answers to this cycle's ramp
      if (lines >= 3 && (busy !== w_busy[0] || ramp !== w_ramp[11:0] || done !== w_done[0] ||
                         code !== w_code[11:0])) begin
        errors = errors + 1;
        if (errors <= 10)
          $display("cycle %0d: busy ramp done code Verilator %0d %0d %0d %0d Icarus %b %0d %b %0d",
                   lines, w_busy, w_ramp, w_done, w_code, busy, ramp, done, code);
      end
      lines = lines + 1;
      @(posedge clk);
      n = $fscanf(fd, "%d %d %d %d %d %d %d %d %d\n", r_rst, r_start, r_conv, r_bits, r_cmp,
                    w_busy, w_ramp, w_done, w_code);
    end
    $fclose(fd);
    if (lines < 100) $fatal(1, "FAIL: record too short (%0d cycles)", lines);
    if (errors != 0) $fatal(1, "FAIL: %0d of %0d cycles differ", errors, lines);
    $display("PASS: %0d cycles replayed, outputs identical to Verilator from cycle 3 on", lines);
    $finish;
  end
endmodule
