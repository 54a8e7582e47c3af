// column_adc.sv of this folder with a realistic bug, for the scoreboard to catch: the ramp
// counter is pre-incremented in the start cycle ("so the DAC settles one cycle early"), so in
// cycle c of a conversion it drives code c + 1 instead of c, and every code comes out one LSB
// high. Otherwise the same file:
//
// A column single-slope ADC controller written from the port contract alone
// (docs/rtl-contract.md, `column_adc`), as a user would write their own block: instead of an
// up-counting cycle counter and a "latched" flag it loads the conversion length into a
// down-counter (non-zero = busy) and remembers whether the comparator has fired.
//
//   rangesim cosim tof-lockin --rtl examples/byo-rtl/tof_lockin/column_adc.sv
//
// replaces every column ADC of the tof-lockin readout with this one; the scoreboard compares the
// codes of every (frame, row, column, tap) with the clock-level model, and the ranges rebuilt
// from them (eq. 2.25) with the kernel's. column_adc_ramp_bug.sv is a copy with an off-by-one.
/* verilator lint_off DECLFILENAME */  // the module keeps the block's name; the file says what it is
module column_adc #(
    parameter int BITS = 12,
    parameter int CYCLE_BITS = 16
) (
    input  logic                  clk,
    input  logic                  rst,
    input  logic                  start_i,
    input  logic [CYCLE_BITS-1:0] conversion_cycles_i,
    input  logic [           4:0] bits_i,
    input  logic                  cmp_i,
    output logic                  busy_o,
    output logic [      BITS-1:0] ramp_o,
    output logic                  done_o,
    output logic [      BITS-1:0] code_o
);
  logic [CYCLE_BITS-1:0] remaining_q;  // cycles of the conversion still to come, this one included
  logic [BITS-1:0] dac_q;              // ramp code driven in this cycle
  logic [BITS-1:0] result_q;
  logic fired_q;                       // the code of this conversion is taken

  wire running = remaining_q != '0;
  wire final_cycle = remaining_q == CYCLE_BITS'(1);
  wire [BITS-1:0] full_scale = BITS'((32'd1 << bits_i) - 32'd1);  // 2^bits_i - 1
  wire take = !fired_q && (cmp_i || dac_q == full_scale);

  always_ff @(posedge clk) begin
    if (rst) begin
      remaining_q <= '0;
      dac_q <= '0;
      result_q <= '0;
      fired_q <= 1'b0;
    end else if (!running) begin
      dac_q <= '0;
      fired_q <= 1'b0;
      if (start_i) begin
        remaining_q <= conversion_cycles_i;
        dac_q <= BITS'(1);  // BUG: the first conversion cycle must drive ramp code 0
      end
    end else begin
      remaining_q <= remaining_q - CYCLE_BITS'(1);
      if (take || (!fired_q && final_cycle)) result_q <= dac_q;  // the comparator, or clipped
      if (take) fired_q <= 1'b1;
      if (dac_q != full_scale) dac_q <= dac_q + BITS'(1);
    end
  end

  assign busy_o = running;
  assign ramp_o = dac_q;
  assign done_o = final_cycle;
  assign code_o = result_q;
endmodule
