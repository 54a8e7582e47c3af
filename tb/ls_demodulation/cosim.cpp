// The built-in ls-demodulation sequencer instance (rtl/CMakeLists.txt: Vls_demodulation_sequencer,
// verilog_parameters() of the default LsDemodulationConfig, checked before each run) through the one harness,
// tb/ls_demodulation/cosim_harness.h.
#include "tb/ls_demodulation/cosim.h"

#include "Vls_demodulation_sequencer.h"
#include "tb/common/instance_check.h"
#include "tb/ls_demodulation/cosim_harness.h"

namespace rangesim::tb {

CosimReport run_ls_demodulation_cosim(const CosimOptions& o) {
  check_instance_parameters("Vls_demodulation_sequencer",
                            verilog_parameters(LsDemodulationConfig{}, "Vls_demodulation_sequencer"));
  return run_ls_demodulation_harness<Vls_demodulation_sequencer>(o, LsDemodulationConfig{}, "ls-demodulation");
}

}  // namespace rangesim::tb
