// The built-in tof-spad TDC group instance (rtl/tof_spad/instances.cmake) through the one harness,
// tb/tof_spad/cosim_harness.h, with the configuration of its instance preset.
#include "tb/tof_spad/cosim.h"

#include "Vtof_spad_sequencer.h"
#include "tb/common/instance_preset.h"
#include "tb/tof_spad/cosim_harness.h"

namespace rangesim::tb {

CosimReport run_tof_spad_cosim(const CosimOptions& o, bool high_rates, const std::string& record) {
  const TofSpadConfig cfg = tof_spad_from_params(instance_preset("Vtof_spad_sequencer"));
  return run_tof_spad_harness<Vtof_spad_sequencer>(o, cfg, high_rates, record, high_rates ? "tdc" : "tof-spad");
}

}  // namespace rangesim::tb
