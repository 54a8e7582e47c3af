#pragma once
// ls-demodulation's non-idealities applied to the kernel's inputs (core/nonideal.h): the point
// spread and crosstalk spread the beam and background photocurrents over the neighbours (at a
// depth step a row then sees the stripe of the next row's depth too: a mixed pixel), then the
// chip's fixed pattern scales each pixel's photocurrents (PRNU), adds its dark-current offset
// (DSNU) and sets its comparator's offset. Same chip (fixed_pattern.seed), same pattern in every
// frame.
#include <cstdint>

#include "core/ls_demodulation/config.h"
#include "systemc/ls_demodulation/sensor_kernel.h"

namespace rangesim::systemc {

void apply_demod_blur(const LsDemodulationConfig& cfg, DemodStimulus& s);
// The fixed pattern of chip `seed` (default: fixed_pattern.seed) on the stimulus's rows.
void apply_demod_fixed_pattern(const LsDemodulationConfig& cfg, DemodStimulus& s, std::uint64_t seed);
void apply_demod_fixed_pattern(const LsDemodulationConfig& cfg, DemodStimulus& s);

}  // namespace rangesim::systemc
