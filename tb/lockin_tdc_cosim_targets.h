#pragma once
// Co-simulation targets of the ls-demodulation / tof-lockin / tof-spad RTL (issue 5b), for
// tb/cosim_targets.cpp to list beside the ls-conventional ones. Sensors first, then blocks.
#include <vector>

#include "tb/cosim_target.h"

namespace rangesim::tb {

std::vector<CosimTarget> lockin_tdc_cosim_targets();

}  // namespace rangesim::tb
