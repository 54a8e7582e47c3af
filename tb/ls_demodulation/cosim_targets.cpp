// The co-simulation target of ls-demodulation (tb/common/cosim_target.h): its readout (frame
// sequencer + the shared address search).
#include "tb/common/cosim_target.h"
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

}  // namespace rangesim::tb
