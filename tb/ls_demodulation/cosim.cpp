// The built-in ls-demodulation sequencer instance (rtl/CMakeLists.txt: Vls_demodulation_sequencer,
// verilog_parameters() of the default LsDemodulationConfig) through the one harness,
// tb/ls_demodulation/cosim_harness.h.
#include "tb/ls_demodulation/cosim.h"

#include "Vls_demodulation_sequencer.h"
#include "tb/ls_demodulation/cosim_harness.h"

namespace rangesim::tb {

CosimReport run_ls_demodulation_cosim(const CosimOptions& o) {
  return run_ls_demodulation_harness<Vls_demodulation_sequencer>(o, LsDemodulationConfig{}, "ls-demodulation");
}

}  // namespace rangesim::tb
