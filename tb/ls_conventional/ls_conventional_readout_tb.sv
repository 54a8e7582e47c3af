// Icarus replay bench of ls_conventional_readout: applies the inputs recorded from a Verilator
// co-simulation run (tb/ls_conventional/cosim.cpp, one $readmemh line {rst, cmp_i} per clock
// period) and dumps the outputs of every period from the reset edge on, in the same %h format
// as the Verilator side. tests/cosim compares the two dumps byte for byte.
//   iverilog -g2012 -P ls_conventional_readout_tb.ROWS=.. (etc.) ... ; vvp sim +stim=F +out=F +cycles=N
// Timing as in the SystemC harness: inputs change just after a rising edge, outputs are read in
// the middle of the cycle (falling edge).
`timescale 1ns / 1ps

module ls_conventional_readout_tb;
  parameter int ROWS = 8;
  parameter int COLUMNS = 16;
  parameter int ADDRESS_BITS = 4;
  parameter int SAMPLINGS = 4;
  parameter int RESET_CYCLES = 3;
  parameter int LATCH_CYCLES = 2;
  parameter int SEARCH_CYCLES = 2;
  parameter int OUTPUT_CYCLES = 5;
  parameter int MAX_CYCLES = 200000;  // capacity of the stimulus memory
  parameter int RESET_EDGES = 3;      // the harness's kResetEdges: outputs from period RESET_EDGES-1
  localparam int SamplingBits = $clog2(SAMPLINGS + 1);
  localparam int CountBits = $clog2(SAMPLINGS + 1);
  localparam int SumBits = ADDRESS_BITS + 1 + $clog2(SAMPLINGS + 1);
  localparam int CentreBits = ADDRESS_BITS + 8;

  logic clk = 0, rst = 1;
  logic [ROWS*COLUMNS-1:0] cmp = '0;
  logic [ROWS*COLUMNS:0] stim[MAX_CYCLES];
  logic [2:0] phase;
  logic pix_reset, latch, search_start, frame_done;
  logic [SamplingBits-1:0] sampling;
  logic [31:0] frame;
  logic [ROWS-1:0] busy, addr_valid, addr_bit, centre_valid;
  logic [ROWS*CentreBits-1:0] centre_q;
  logic [ROWS*SumBits-1:0] sum;
  logic [ROWS*CountBits-1:0] count;

  ls_conventional_readout #(
      .ROWS(ROWS), .COLUMNS(COLUMNS), .ADDRESS_BITS(ADDRESS_BITS), .SAMPLINGS(SAMPLINGS),
      .RESET_CYCLES(RESET_CYCLES), .LATCH_CYCLES(LATCH_CYCLES), .SEARCH_CYCLES(SEARCH_CYCLES),
      .OUTPUT_CYCLES(OUTPUT_CYCLES)
  ) dut (
      .clk, .rst, .cmp_i(cmp), .phase_o(phase), .pix_reset_o(pix_reset), .latch_o(latch),
      .search_start_o(search_start), .frame_done_o(frame_done), .sampling_o(sampling),
      .frame_o(frame), .busy_o(busy), .addr_valid_o(addr_valid), .addr_bit_o(addr_bit),
      .centre_valid_o(centre_valid), .centre_q_o(centre_q), .sum_o(sum), .count_o(count)
  );

  string stim_path, out_path;
  int cycles, fd;
  initial begin
    if (!$value$plusargs("stim=%s", stim_path) || !$value$plusargs("out=%s", out_path) ||
        !$value$plusargs("cycles=%d", cycles)) begin
      $display("FAIL: need +stim=FILE +out=FILE +cycles=N");
      $finish;
    end
    if (cycles > MAX_CYCLES) begin
      $display("FAIL: %0d cycles > MAX_CYCLES %0d", cycles, MAX_CYCLES);
      $finish;
    end
    $readmemh(stim_path, stim, 0, cycles - 1);
    fd = $fopen(out_path, "w");
    for (int i = 0; i < cycles; i++) begin
      #5 clk = 1;  // rising edge i: the DUT samples the inputs of period i - 1
      #1 {rst, cmp} = stim[i];
      #4 clk = 0;  // middle of period i
      #1 if (i >= RESET_EDGES - 1)
        $fwrite(fd, "%h %h %h %h %h %h %h %h %h %h %h %h %h %h\n", phase, pix_reset, latch,
                search_start, frame_done, sampling, frame, busy, addr_valid, addr_bit,
                centre_valid, centre_q, sum, count);
    end
    $fclose(fd);
    $display("PASS: replayed %0d cycles", cycles);
    $finish;
  end
endmodule
