// Icarus replay of a Verilator co-simulation run of rtl/tof_spad/tof_spad_sequencer.sv with rtl/tof_spad/tdc.sv
// and rtl/tof_spad/tdc_histogram.sv (ctest label iverilog): the recorded per-cycle inputs (hits, fine
// phases, corrections) and the outputs Verilator produced (TDC codes, grants, lost hits,
// histogram words, peaks, centroid sums); the same RTL under Icarus must give identical
// outputs in every cycle after reset. +record=<file>. Prints PASS.
`timescale 1ns / 1ps

module tof_spad_sequencer_replay_tb;
  logic clk = 1'b0, rst = 1'b1, start = 1'b0;
  logic [7:0] rows = 8'd1, w = 8'd1;
  logic [23:0] laser = 24'd1;
  logic [10:0] np = 11'd1, nc = 11'd1, be = '0, bo = '0;
  logic [3:0] hit = '0;
  logic [63:0] fine = '0;
  logic [11:0] corr = '0;
  logic ready, ev, ovf, word_valid, peak_valid, saturated;
  logic [1:0] phase, word_column, peak_column;
  logic [7:0] row;
  logic [10:0] code, word_code, peak_code;
  logic [3:0] grant;
  logic [2:0] lost;
  logic [15:0] word, peak_count;
  logic [39:0] num;
  logic [31:0] den;

  tof_spad_sequencer dut (
      .clk,
      .rst,
      .start_i(start),
      .rows_i(rows),
      .laser_cycles_i(laser),
      .phase_bins_i(np),
      .codes_i(nc),
      .block_event_i(be),
      .block_overflow_i(bo),
      .cycles_per_word_i(w),
      .hit_i(hit),
      .fine_i(fine),
      .corr_i(corr),
      .ready_o(ready),
      .phase_o(phase),
      .row_o(row),
      .tdc_event_o(ev),
      .tdc_overflow_o(ovf),
      .tdc_code_o(code),
      .tdc_grant_o(grant),
      .tdc_lost_o(lost),
      .word_valid_o(word_valid),
      .word_column_o(word_column),
      .word_code_o(word_code),
      .word_o(word),
      .peak_valid_o(peak_valid),
      .peak_column_o(peak_column),
      .peak_code_o(peak_code),
      .peak_count_o(peak_count),
      .centroid_num_o(num),
      .centroid_den_o(den),
      .saturated_o(saturated)
  );

  always #5 clk = ~clk;

  integer fd, n, lines = 0, errors = 0, compared = 0;
  integer r_rst, r_start, r_rows, r_laser, r_np, r_nc, r_be, r_bo, r_w, r_hit, r_corr;
  integer w_phase, w_row, w_ev, w_ovf, w_code, w_grant, w_lost, w_wv, w_word, w_pv, w_pcode;
  integer w_pcount, w_den;
  reg [63:0] r_fine, w_num;
  reg [1023:0] path;

  // Outputs are compared once the histogram has cleared its memory (before that Verilator's
  // randomised and Icarus's X initial memory may differ in what is still being cleared).
  task automatic compare;
    if (phase !== w_phase[1:0] || row !== w_row[7:0] || ev !== w_ev[0] || ovf !== w_ovf[0] ||
        code !== w_code[10:0] || grant !== w_grant[3:0] || lost !== w_lost[2:0] ||
        word_valid !== w_wv[0] || (word_valid && word !== w_word[15:0]) ||
        peak_valid !== w_pv[0] || (peak_valid && (peak_code !== w_pcode[10:0] ||
        peak_count !== w_pcount[15:0] || num !== w_num[39:0] || den !== w_den))) begin
      errors = errors + 1;
      if (errors <= 10)
        $display("cycle %0d: Verilator phase %0d ev %0d code %0d grant %0d lost %0d word %0d | Icarus %0d %b %0d %0d %0d %0d",
                 lines, w_phase, w_ev, w_code, w_grant, w_lost, w_word, phase, ev, code, grant,
                 lost, word);
    end
    compared = compared + 1;
  endtask

  initial begin
    if (!$value$plusargs("record=%s", path)) $fatal(1, "FAIL: no +record=<file>");
    fd = $fopen(path, "r");
    if (fd == 0) $fatal(1, "FAIL: cannot open the record");
    n = $fscanf(fd, "%d %d %d %d %d %d %d %d %d %d %h %d %d %d %d %d %d %d %d %d %d %d %d %d %d %d\n",
                r_rst, r_start, r_rows, r_laser, r_np, r_nc, r_be, r_bo, r_w, r_hit, r_fine, r_corr,
                w_phase, w_row, w_ev, w_ovf, w_code, w_grant, w_lost, w_wv, w_word, w_pv, w_pcode,
                w_pcount, w_num, w_den);
    while (n == 26) begin
      #1;
      rst = r_rst[0];
      start = r_start[0];
      rows = r_rows[7:0];
      laser = r_laser[23:0];
      np = r_np[10:0];
      nc = r_nc[10:0];
      be = r_be[10:0];
      bo = r_bo[10:0];
      w = r_w[7:0];
      hit = r_hit[3:0];
      fine = r_fine;
      corr = r_corr[11:0];
      @(negedge clk);
      if (lines >= 3 && ready !== 1'bx && !rst && (dut.u_hist.state_q != 0)) compare();
      lines = lines + 1;
      @(posedge clk);
      n = $fscanf(fd, "%d %d %d %d %d %d %d %d %d %d %h %d %d %d %d %d %d %d %d %d %d %d %d %d %d %d\n",
                  r_rst, r_start, r_rows, r_laser, r_np, r_nc, r_be, r_bo, r_w, r_hit, r_fine,
                  r_corr, w_phase, w_row, w_ev, w_ovf, w_code, w_grant, w_lost, w_wv, w_word,
                  w_pv, w_pcode, w_pcount, w_num, w_den);
    end
    $fclose(fd);
    if (compared < 1000) $fatal(1, "FAIL: too few cycles compared (%0d)", compared);
    if (errors != 0) $fatal(1, "FAIL: %0d of %0d cycles differ", errors, compared);
    $display("PASS: %0d cycles identical to Verilator (%0d replayed)", compared, lines);
    $finish;
  end
endmodule
