#pragma once
// tof-lockin's non-idealities applied to the kernels' inputs (core/nonideal.h,
// golden/tof_lockin/nonideal.h): a second return (multipath), the point spread and crosstalk
// (each pixel also receives its neighbours' returns, at their own delays: a pixel at a depth step
// mixes two depths) and the chip's fixed pattern (PRNU on the photocurrents, each FD's gain and
// dark current). The kernels then take the stimulus as they always did.
#include <cstdint>
#include <vector>

#include "core/tof_lockin/config.h"
#include "systemc/tof_lockin/kernel_types.h"

namespace rangesim::systemc::lockin {

// Adds the second return of multipath.* to every return of every pixel.
void add_multipath(const TofLockinConfig& cfg, std::vector<LockinPixelStimulus>& st);

// Spreads every pixel's returns and background over its neighbours by blur.* (rows x columns,
// row-major); returns at the same delay are merged.
void apply_blur(const TofLockinConfig& cfg, std::vector<LockinPixelStimulus>& st, int rows, int columns);

// The fixed pattern of chip `seed` on pixels (first_row + r, first_column + c).
void apply_fixed_pattern(const TofLockinConfig& cfg, std::uint64_t seed, std::vector<LockinPixelStimulus>& st, int rows,
                         int columns, int first_row = 0, int first_column = 0);

// All three, in the order light meets them: multipath, the optics, the chip (fixed_pattern.seed).
void apply_nonideal(const TofLockinConfig& cfg, std::vector<LockinPixelStimulus>& st, int rows, int columns);

}  // namespace rangesim::systemc::lockin
