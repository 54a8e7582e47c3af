#pragma once
// tof-spad's non-idealities on the kernels' inputs (core/nonideal.h), in the order light meets
// them: a second return of every echo (multipath), the lens's point spread and the pixels'
// crosstalk (a pixel also receives its neighbours' echoes, at their delays: a pixel at a depth step
// sees two echoes), then the chip's fixed pattern: each SPAD's photon detection efficiency differs
// from the mean by the PRNU draw (it scales the pixel's signal and background count rates) and its
// dark count rate by the DSNU draw (never below none at all), keyed by the chip's seed and the
// pixel, the same in every frame. The kernels take the result as per-pixel rates.
#include <cstdint>

#include "core/tof_spad/config.h"
#include "systemc/tof_spad/pixel_kernel.h"
#include "systemc/tof_spad/sensor_kernel.h"

namespace rangesim::systemc::spad {

PixelRates with_fixed_pattern(const TofSpadConfig& cfg, std::uint64_t seed, PixelRates r, int row, int column);

// Every echo of `r` again multipath.relative_amplitude as strong, multipath.extra_path_m later.
PixelRates with_multipath(const TofSpadConfig& cfg, PixelRates r);

// The scene's rates through the optics (blur.*: each pixel's echoes and background spread over
// its neighbours, echoes at one delay merged; the array is rows x columns, its edges continued)
// and the chip (fixed_pattern.*, chip `seed`), multipath first.
RateSource chip_rates(const TofSpadConfig& cfg, std::uint64_t seed, RateSource scene, int rows, int columns);

}  // namespace rangesim::systemc::spad
