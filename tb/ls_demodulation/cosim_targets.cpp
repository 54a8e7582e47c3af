// The co-simulation target of ls-demodulation (tb/common/cosim_target.h): its readout (frame
// sequencer + the shared address search).
#include "tb/common/cosim_target.h"
#include "tb/common/rtl_build.h"
#include "tb/ls_demodulation/cosim.h"
#include "tb/ls_demodulation/verilog_parameters.h"

namespace rangesim::tb {

std::vector<CosimTarget> ls_demodulation_cosim_targets() {
  return {
      {"ls-demodulation",
       "ls-demodulation frame sequencer + address search vs the ticking sensor kernel: phases, "
       "address stream, row results, centres",
       {"dropped_row", "address_bit_flip"},
       &run_ls_demodulation_cosim},
  };
}

namespace {
RtlBuildSpec preset_sequencer(const ParamSet& preset) {
  return {"ls_demodulation",
          "ls_demodulation_sequencer",
          verilog_parameters(ls_demodulation_from_params(preset), preset.origin()),
          "tb/ls_demodulation/cosim_harness.h",
          "rangesim::tb::run_ls_demodulation_preset",
          {}};
}
}  // namespace

// `rangesim cosim <ls-demodulation preset>`: the sequencer at the preset's array width and readout.
std::vector<PresetCosim> ls_demodulation_preset_cosims() {
  return {{"ls-demodulation", "ls-demodulation", "rtl/ls_demodulation/instances/readout.toml", &preset_sequencer}};
}

}  // namespace rangesim::tb
