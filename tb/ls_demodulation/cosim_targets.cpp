// The co-simulation target of ls-demodulation (tb/common/cosim_target.h): its readout (frame
// sequencer + the shared address search).
#include "tb/common/cosim_target.h"
#include "tb/common/rtl_build.h"
#include "tb/ls_demodulation/cosim.h"

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

// No co-simulation at a preset's own parameters yet.
std::vector<PresetCosim> ls_demodulation_preset_cosims() { return {}; }

}  // namespace rangesim::tb
