#pragma once
// ls-conventional's non-idealities as the pixel array's per-pixel inputs (core/nonideal.h,
// frame_stimulus.h): the chip's fixed pattern (PRNU on the photo swing, DSNU on the dark swing,
// the comparator offset), drawn once per chip from fixed_pattern.seed and the pixel only, and the
// point spread and crosstalk of the spot across rows and columns (at a depth step a row then
// sees the stripe of its neighbour rows too: two spot profiles, a mixed pixel). The scene adapter
// (scene_optics.h) and the Monte Carlo (montecarlo.cpp, a chip per trial) apply them.
#include <cstdint>
#include <vector>

#include "core/ls_conventional/config.h"
#include "systemc/common/optical_blur.h"
#include "systemc/ls_conventional/frame_stimulus.h"

namespace rangesim::systemc {

// The fixed pattern of chip `seed` over the config's rows x columns; the terms that are off stay
// empty. Gain 1 + p z clipped at 0; dark current I_dark + d z' clipped at 0 (a current, then a
// swing I T / C); offset o z''. z, z', z'' independent standard normals per pixel.
PixelPattern make_pixel_pattern(const LsConventionalConfig& cfg, std::uint64_t seed);

// The taps of cfg.blur, or none when they are the identity (a diffraction-limited spot of a few
// hundredths of a pixel): then nothing is spread and the stimulus stays per row.
std::vector<BlurTap> ls_conventional_blur_taps(const LsConventionalConfig& cfg);

// Spreads the spot swings of every row of `s` (all rows filled) by `taps` into s.signal_px_V for
// the rows of the band s.first_row .. + s.row_count (others 0). The background stays per row.
void spread_spot(const LsConventionalConfig& cfg, const std::vector<BlurTap>& taps, FrameStimulus& s);

}  // namespace rangesim::systemc
