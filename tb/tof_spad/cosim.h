#pragma once
// Co-simulation of the tof-spad readout RTL: rtl/tof_spad/tof_spad_sequencer.sv (rtl/tof_spad/tdc.sv +
// tdc_histogram.sv, one TDC group of 4 columns) against the SystemC kernels
// (systemc/tof_spad: SpadPixelKernel avalanches, TdcGroupKernel per hit, TofSpadKernel
// histograms and schedule). Elaborates SystemC: one run per process.
//   tof-spad  rows of integration + histogram readout: TDC codes / grants / lost hits per
//             cycle, histogram bins, peaks, centroid sums, phase boundaries, the estimator
//             (golden) on the RTL histograms; faults tdc_code_off_by_one, dropped_histogram_count
//   tdc       one row at high count rates (many same-cycle collisions, dead time, overflow):
//             the TDC and its arbitration; fault tdc_code_off_by_one
#include <string>

#include "tb/common/cosim_target.h"

namespace rangesim::tb {

// high_rates: the `tdc` target. record_path: per-cycle inputs and RTL outputs for the Icarus
// replay (tb/tof_spad/tof_spad_sequencer_replay_tb.sv). The harness: tb/tof_spad/cosim_harness.h.
CosimReport run_tof_spad_cosim(const CosimOptions& options, bool high_rates, const std::string& record_path = {});

}  // namespace rangesim::tb
