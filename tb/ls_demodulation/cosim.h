#pragma once
// Co-simulation of the ls-demodulation readout: rtl/ls_demodulation/ls_demodulation_sequencer.sv (frame
// sequencer + the chained address search, preset instance 120 columns, B = 7, S = 26) against
// DemodSensorKernel ticking cycle by cycle (systemc/ls_demodulation). Per cycle: phase, integrator
// reset, decision latch, row, search start and the address stream; per row and decision: found,
// left and right address; per frame and row: the centre (mean of (left + right) / 2 over the
// detecting decisions) rebuilt from the RTL against the kernel's frame result.
// Odd seeds run noise-free, and then each row's centre is also checked against the golden
// model (golden_checks). Faults: dropped_row (the scoreboard misses one RTL row result), address_bit_flip.
// Elaborates SystemC: one run per process.
#include "tb/common/cosim_target.h"

namespace rangesim::tb {

CosimReport run_ls_demodulation_cosim(const CosimOptions& options);

}  // namespace rangesim::tb
