// Readout of tof-lockin: the frame sequencer (with its gate generator) and a bank of column
// single-slope ADCs, one per (column, tap), started together by the sequencer's adc_start_o.
// The analog side (each ADC's comparator, V_in against the ramp) stays outside: cmp_i.
// Reference: systemc/tof_lockin/sensor_kernel.h, TofLockinSensorKernel in tick mode.
//
// Channel i = 2 column + tap converts that column's tap (FD1, FD2) of the row in readout; its
// ramp and code are the fields [i*BITS +: BITS] of ramp_o and code_o. CHANNELS is the number of
// ADCs built, at least twice the columns the harness drives (the rest see cmp_i = 0).
module tof_lockin_readout #(
    parameter int CYCLE_BITS = 16,  // T0, T_rep, conversion and output cycle counters
    parameter int ACC_BITS   = 20,  // accumulations per frame
    parameter int ROW_BITS   = 12,  // rows
    parameter int FRAME_BITS = 16,  // frames per run
    parameter int BITS       = 12,  // ADC code width
    parameter int CHANNELS   = 8    // column ADCs: 2 taps x columns
) (
    input  logic                     clk,
    input  logic                     rst,
    input  logic                     start_i,
    input  logic [   CYCLE_BITS-1:0] t0_cycles_i,
    input  logic [   CYCLE_BITS-1:0] period_cycles_i,
    input  logic [     ACC_BITS-1:0] accumulations_i,
    input  logic [     ROW_BITS-1:0] rows_i,               // >= 1
    input  logic [   CYCLE_BITS-1:0] conversion_cycles_i,  // >= 1
    input  logic [   CYCLE_BITS-1:0] output_cycles_i,      // >= 1
    input  logic [   FRAME_BITS-1:0] frames_i,             // >= 1
    input  logic                     ambient_i,            // odd frames are ambient (LED off)
    input  logic [              4:0] bits_i,               // ADC resolution in use, 1 .. BITS
    input  logic [     CHANNELS-1:0] cmp_i,                // per channel: V_in < ramp of this cycle
    output logic                     busy_o,
    output logic [              2:0] phase_o,
    output logic                     tx1_o,
    output logic                     tx2_o,
    output logic                     txd_o,
    output logic                     light_o,
    output logic                     adc_start_o,          // next cycle is a row's first conversion cycle
    output logic [     ROW_BITS-1:0] row_o,                // row in readout
    output logic [   FRAME_BITS-1:0] frame_o,
    output logic                     frame_done_o,         // last cycle of a frame
    output logic [     CHANNELS-1:0] adc_busy_o,           // per channel: conversion in progress
    output logic [     CHANNELS-1:0] adc_done_o,           // per channel: last conversion cycle
    output logic [CHANNELS*BITS-1:0] ramp_o,               // per channel: ramp DAC code of this cycle
    output logic [CHANNELS*BITS-1:0] code_o                // per channel: result of the last conversion
);
  tof_lockin_sequencer #(
      .CYCLE_BITS(CYCLE_BITS),
      .ACC_BITS  (ACC_BITS),
      .ROW_BITS  (ROW_BITS),
      .FRAME_BITS(FRAME_BITS)
  ) u_sequencer (
      .clk,
      .rst,
      .start_i,
      .t0_cycles_i,
      .period_cycles_i,
      .accumulations_i,
      .rows_i,
      .conversion_cycles_i,
      .output_cycles_i,
      .frames_i,
      .ambient_i,
      .busy_o,
      .phase_o,
      .tx1_o,
      .tx2_o,
      .txd_o,
      .light_o,
      .adc_start_o,
      .row_o,
      .frame_o,
      .frame_done_o
  );

  for (genvar i = 0; i < CHANNELS; i++) begin : g_adc
    column_adc #(
        .BITS      (BITS),
        .CYCLE_BITS(CYCLE_BITS)
    ) u_adc (
        .clk,
        .rst,
        .start_i(adc_start_o),
        .conversion_cycles_i,
        .bits_i,
        .cmp_i(cmp_i[i]),
        .busy_o(adc_busy_o[i]),
        .ramp_o(ramp_o[i*BITS+:BITS]),
        .done_o(adc_done_o[i]),
        .code_o(code_o[i*BITS+:BITS])
    );
  end
endmodule
