#pragma once
// tof-spad's fixed pattern on the kernels' inputs (core/nonideal.h): each SPAD's photon detection
// efficiency differs from the mean by the PRNU draw (it scales the pixel's signal and background
// count rates) and its dark count rate by the DSNU draw (never below none at all). Keyed by the
// chip's seed and the pixel, the same in every frame.
#include <cstdint>

#include "core/tof_spad/config.h"
#include "systemc/tof_spad/pixel_kernel.h"

namespace rangesim::systemc::spad {

PixelRates with_fixed_pattern(const TofSpadConfig& cfg, std::uint64_t seed, PixelRates r, int row, int column);

}  // namespace rangesim::systemc::spad
