// Self-checking Icarus testbench of rtl/common/address_search.sv (ctest label `rtl`): proves the RTL
// also runs on a second simulator and re-checks the documented cycle schedule independently of
// the C++ kernel. Back-to-back operations (start in the cycle after done_o), random rows plus the
// corner cases (empty, full, single column at each end). Prints "PASS" or "$fatal"s.
`timescale 1ns / 1ps

module address_search_tb;
  localparam int COLUMNS = 16;
  localparam int ADDRESS_BITS = 4;
  localparam int SEARCH_CYCLES = 2;
  localparam int OPERATIONS = 300;

  logic clk = 1'b0, rst = 1'b1, start = 1'b0;
  logic [COLUMNS-1:0] act = '0;
  logic busy, found, addr_valid, addr_bit, done;

  address_search #(
      .COLUMNS(COLUMNS),
      .ADDRESS_BITS(ADDRESS_BITS),
      .SEARCH_CYCLES(SEARCH_CYCLES)
  ) dut (
      .clk, .rst, .start_i(start), .act_i(act), .busy_o(busy), .found_o(found),
      .addr_valid_o(addr_valid), .addr_bit_o(addr_bit), .done_o(done)
  );

  always #5 clk = ~clk;

  // Row under test and its reference edges.
  function automatic logic [COLUMNS-1:0] row_for(int op);
    case (op)
      0: row_for = '0;
      1: row_for = '1;
      2: row_for = 16'h0001;
      3: row_for = 16'h8000;
      default: row_for = COLUMNS'($urandom) & COLUMNS'($urandom);  // sparse-ish
    endcase
  endfunction

  int errors = 0;
  initial begin
    logic [COLUMNS-1:0] row;
    int left, right, k, expect_done;
    logic [2*ADDRESS_BITS-1:0] bits, want;
    repeat (2) @(posedge clk);
    rst <= 1'b0;
    for (int op = 0; op < OPERATIONS; op++) begin
      row = row_for(op);
      left = 0;
      right = 0;
      for (int c = COLUMNS - 1; c >= 0; c--) if (row[c]) left = c;
      for (int c = 0; c < COLUMNS; c++) if (row[c]) right = c;
      want = {ADDRESS_BITS'(left), ADDRESS_BITS'(right)};
      expect_done = (row != 0) ? SEARCH_CYCLES + 2 * ADDRESS_BITS : SEARCH_CYCLES;
      // cycle k = 0: start high
      start <= 1'b1;
      act <= row;
      @(posedge clk);
      start <= 1'b0;
      act <= ~row;  // must not matter after the latch
      bits = '0;
      for (k = 1; k <= expect_done; k++) begin
        @(negedge clk);
        if (found !== (row != 0)) begin
          $display("op %0d cycle %0d: found_o %b", op, k, found);
          errors++;
        end
        if (addr_valid !== (row != 0 && k > SEARCH_CYCLES)) begin
          $display("op %0d cycle %0d: addr_valid_o %b", op, k, addr_valid);
          errors++;
        end
        if (addr_valid) bits = {bits[2*ADDRESS_BITS-2:0], addr_bit};
        if (done !== (k == expect_done)) begin
          $display("op %0d cycle %0d: done_o %b", op, k, done);
          errors++;
        end
        @(posedge clk);
      end
      if (row != 0 && bits !== want) begin
        $display("op %0d: stream %b expected %b", op, bits, want);
        errors++;
      end
      #1;  // let the edge settle (NBA) before looking at busy_o
      if (busy) begin
        $display("op %0d: still busy after done", op);
        errors++;
      end
    end
    if (errors != 0) $fatal(1, "FAIL: %0d errors", errors);
    $display("PASS");
    $finish;
  end

  initial begin
    #1000000 $fatal(1, "FAIL: cycle limit");
  end
endmodule
