// Column single-slope ADC controller of tof-lockin: a counter drives the ramp DAC while the
// analog comparator (outside, in the testbench / pixel column) watches V_in against the ramp.
// Reference: systemc/tof_lockin/column_adc_kernel.h, ColumnAdcKernel: code = floor(V / LSB)
// clipped to 0 .. 2^bits_i - 1, conversion_cycles per conversion (>= 2^BITS for full range).
//
// Cycle c = 0 .. conversion_cycles_i - 1 of a conversion: ramp_o = c (ramp voltage (c+1) LSB in
// that cycle); cmp_i = 1 means V_in < ramp. The code latches at the first cycle with cmp_i = 1
// (code = c), else saturates at the top code (the counter never wraps: it stops at the top).
// start_i sampled at a rising edge -> the next cycle is c = 0; done_o in the last cycle; code_o
// valid from the cycle after done_o until the next start.
module column_adc #(
    parameter int BITS = 12,        // code width
    parameter int CYCLE_BITS = 16   // width of the conversion cycle counter
) (
    input  logic                  clk,
    input  logic                  rst,                  // synchronous, active high
    input  logic                  start_i,              // begin a conversion (ignored while busy)
    input  logic [CYCLE_BITS-1:0] conversion_cycles_i,  // >= 1 (>= 2^bits_i for full range)
    input  logic [           4:0] bits_i,               // resolution in use, 1 .. BITS
    input  logic                  cmp_i,                // comparator: V_in < ramp of this cycle
    output logic                  busy_o,
    output logic [      BITS-1:0] ramp_o,               // ramp DAC code of this cycle
    output logic                  done_o,               // last cycle of the conversion
    output logic [      BITS-1:0] code_o                // result of the last conversion
);
  logic busy_q, latched_q;
  logic [CYCLE_BITS-1:0] cyc_q;
  logic [BITS-1:0] ramp_q, code_q;

  wire last = cyc_q == conversion_cycles_i - 1'b1;
  wire [BITS-1:0] top = {BITS{1'b1}} >> (BITS[4:0] - bits_i);  // 2^bits_i - 1
  wire at_top = ramp_q == top;

  always_ff @(posedge clk) begin
    if (rst) begin
      busy_q <= 1'b0;
      latched_q <= 1'b0;
      cyc_q <= '0;
      ramp_q <= '0;
      code_q <= '0;
    end else if (!busy_q) begin
      busy_q <= start_i;
      latched_q <= 1'b0;
      cyc_q <= '0;
      ramp_q <= '0;
    end else begin
      if (!latched_q && (cmp_i || at_top)) begin
        code_q <= ramp_q;
        latched_q <= 1'b1;
      end else if (!latched_q && last) begin
        code_q <= ramp_q;  // short conversion: clipped at the ramp reached
      end
      if (!at_top) ramp_q <= ramp_q + 1'b1;  // saturate: never wraps
      cyc_q <= cyc_q + 1'b1;
      if (last) busy_q <= 1'b0;
    end
  end

  always_comb begin
    busy_o = busy_q;
    ramp_o = ramp_q;
    done_o = busy_q && last;
    code_o = code_q;
  end

  always @(posedge clk) begin
    if (!rst && busy_q) begin
`ifdef __ICARUS__
      if (cyc_q >= conversion_cycles_i) $error("a_adc_cycle_in_range: conversion counter wrapped");
      if (bits_i == 0 || bits_i > BITS[4:0]) $error("a_adc_bits_in_range: bits_i outside 1 .. BITS");
`else
      a_adc_cycle_in_range : assert (cyc_q < conversion_cycles_i)
      else $error("conversion counter past conversion_cycles (would wrap silently)");
      a_adc_bits_in_range : assert (bits_i != 0 && bits_i <= BITS[4:0])
      else $error("bits_i outside 1 .. BITS");
`endif
    end
  end
endmodule
