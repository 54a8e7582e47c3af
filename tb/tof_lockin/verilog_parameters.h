#pragma once
// The tof-lockin readout RTL (rtl/tof_lockin/: lockin_gate_generator, column_adc,
// tof_lockin_sequencer, and tof_lockin_readout: the sequencer with a bank of column ADCs) takes its timing as run-time inputs (T0, T_rep, N_acc, ADC resolution
// and conversion cycles, output cycles, rows, frames), so one verilated instance serves every
// preset whose timing fits its counters. The counter widths below are those maxima: the one
// place they are set (rtl/tof_lockin/instances/readout.toml is verilated with them), checked
// against a preset before its timing is driven into the RTL.
#include <string>

#include "core/tof_lockin/config.h"
#include "tb/common/verilog_parameters.h"

namespace rangesim::tb {

struct TofLockinRtlShape {
  int cycle_bits = 16;  // CYCLE_BITS: T0, T_rep, conversion and output cycle counters
  int acc_bits = 20;    // ACC_BITS: accumulations per frame
  int row_bits = 12;    // ROW_BITS: rows
  int frame_bits = 16;  // FRAME_BITS: frames per run
  int adc_bits = 12;    // BITS of column_adc: widest ADC code
  // CHANNELS of tof_lockin_readout: column ADCs (2 taps x columns) of the co-simulated readout.
  // The co-simulation draws a reduced array of 1..adc_channels / 2 columns.
  int adc_channels = 8;
};

// UserError naming `origin`, the key and the allowed range when a timing of `cfg` does not fit.
TofLockinRtlShape tof_lockin_rtl_shape(const TofLockinConfig& cfg, const std::string& origin);

}  // namespace rangesim::tb
