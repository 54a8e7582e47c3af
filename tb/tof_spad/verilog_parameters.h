#pragma once
// The one map from a tof-spad config to the RTL of one TDC group, rtl/tof_spad/tof_spad_sequencer.sv
// (tdc.sv + tdc_histogram.sv): the group's width comes from tdc.columns_per_tdc, the code range
// from tdc.bits; the remaining widths are the RTL's (they bound its run-time inputs: rows per
// run, laser cycles per row, interpolator and bin-correction inputs, saturating bin counters).
// Used for the built-in instance (at build time, from rtl/tof_spad/instances/tdc_group.toml), for a
// preset's own (`rangesim cosim <preset.toml>`) and by the harness (tb/tof_spad/cosim_harness.h)
// for its field widths.
#include <string>

#include "core/tof_spad/config.h"
#include "tb/common/verilog_parameters.h"

namespace rangesim::tb {

struct TofSpadRtlShape {
  int cpt = 4;           // CPT: columns of the group (tdc.columns_per_tdc)
  int col_bits = 2;      // COL_BITS: column index width, clog2(CPT) (at least 1)
  int bin_bits = 11;     // BIN_BITS: phase-bin / code width, tdc.bits + 1 (Np may exceed the codes)
  int codes_max = 1024;  // CODES_MAX: histogram words per column, 2^tdc.bits
  int fine_bits = 16;    // FINE_BITS: interpolator phase per column
  int corr_bits = 3;     // CORR_BITS: signed bin correction per column
  int count_bits = 16;   // COUNT_BITS: bin counters (saturating)
  int row_bits = 8;      // ROW_BITS: rows per run
  int laser_bits = 24;   // LASER_BITS: laser cycles per row
};

// UserError naming `origin` and the key when the RTL cannot take the config.
TofSpadRtlShape tof_spad_rtl_shape(const TofSpadConfig& cfg, const std::string& origin);
VerilogParameters verilog_parameters(const TofSpadConfig& cfg, const std::string& origin);

}  // namespace rangesim::tb
