// The built-in tof-spad TDC group instance (rtl/CMakeLists.txt: Vtof_spad_sequencer, the widths of
// verilog_parameters() of the default TofSpadConfig, checked before each run) through the one harness,
// tb/tof_spad/cosim_harness.h.
#include "tb/tof_spad/cosim.h"

#include "Vtof_spad_sequencer.h"
#include "tb/common/instance_check.h"
#include "tb/tof_spad/cosim_harness.h"

namespace rangesim::tb {

CosimReport run_tof_spad_cosim(const CosimOptions& o, bool high_rates, const std::string& record) {
  check_instance_parameters("Vtof_spad_sequencer", verilog_parameters(TofSpadConfig{}, "Vtof_spad_sequencer"));
  return run_tof_spad_harness<Vtof_spad_sequencer>(o, TofSpadConfig{}, high_rates, record,
                                                   high_rates ? "tdc" : "tof-spad");
}

}  // namespace rangesim::tb
