#pragma once
// Co-simulation of two ls-conventional readout blocks on their own, each verilated small
// instance beside its cycle kernel under SystemC, compared pin by pin every cycle:
//   centre_processor        Vcentre_processor_small vs systemc::CentreProcessorKernel, on random
//                           address streams (contiguous 2B bits, random gaps) and clears;
//   multisampling_sequencer Vmultisampling_sequencer_small vs systemc::MultisamplingSequencerKernel,
//                           free-running frame accesses with random reset pulses.
// Each elaborates SystemC: one per process.
#include "tb/common/cosim_target.h"

namespace rangesim::tb {

// Faults: "centre_off_by_one" (RTL centre seen 1 LSB high once), "count_wrap" (the stimulus
// sends SAMPLINGS + 1 streams without a clear: assertion a_count_no_wrap must fire).
CosimReport run_centre_processor_cosim(const CosimOptions& options);

// Faults: "search_start_late" (the RTL's search_start seen one cycle late once).
CosimReport run_multisampling_sequencer_cosim(const CosimOptions& options);

}  // namespace rangesim::tb
