// The built-in ls-demodulation sequencer instance (rtl/ls_demodulation/instances.cmake) through the
// one harness, tb/ls_demodulation/cosim_harness.h, with the configuration of its instance preset.
#include "tb/ls_demodulation/cosim.h"

#include "Vls_demodulation_sequencer.h"
#include "tb/common/instance_preset.h"
#include "tb/ls_demodulation/cosim_harness.h"

namespace rangesim::tb {

CosimReport run_ls_demodulation_cosim(const CosimOptions& o) {
  const LsDemodulationConfig cfg = ls_demodulation_from_params(instance_preset("Vls_demodulation_sequencer"));
  return run_ls_demodulation_harness<Vls_demodulation_sequencer>(o, cfg, "ls-demodulation");
}

}  // namespace rangesim::tb
