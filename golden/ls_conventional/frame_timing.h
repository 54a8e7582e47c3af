#pragma once
// Frame timing of ls-conventional from its clock schedule.
//
// One frame access (one sheet-beam position) is: pixel reset, then N samplings each made of a
// comparator latch, the chained-search settle and the bit-serial stream of the activated run's
// column addresses (left and right edge), then the output of the centres from the row-parallel
// processors. Rows run in parallel, so the row count does not enter.
//   cycles = reset + N (latch + search + addresses_per_sampling * address_bits) + output
// A range map is `beam_positions` frame accesses.
#include "core/ls_conventional/config.h"
#include "golden/common/frame_timing.h"

namespace rangesim::golden {

FrameTiming frame_timing(const FrameTimingConfig& timing, int samplings);

}  // namespace rangesim::golden
