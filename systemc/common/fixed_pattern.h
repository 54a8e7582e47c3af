#pragma once
// The chip's fixed pattern (core/nonideal.h): per-pixel draws that are the same in every frame,
// keyed by the chip's seed, the quantity and the pixel only (never the frame), from the same
// counter-based streams as the noise (systemc/common/random_stream.h) but in a key space of
// their own. The sensors' scene adapters apply them to the kernels' inputs (a pixel's
// photocurrent, dark current, tap gain, comparator offset), so a kernel needs no knowledge of
// the fixed pattern beyond taking per-pixel inputs.
#include <cstdint>

namespace rangesim::systemc {

// What a draw is for: each quantity has its own independent draws.
enum class FixedPatternDraw : std::uint32_t { Gain = 1, Dark = 2, Tap0 = 3, Tap1 = 4, ComparatorOffset = 5, Dark1 = 6 };

// Standard normal value of pixel (row, column) of chip `seed` for `what`.
double fixed_pattern_normal(std::uint64_t seed, FixedPatternDraw what, int row, int column);

// The pixel's relative gain 1 + rms z, clipped at 0 (a gain cannot be negative).
double fixed_gain(std::uint64_t seed, FixedPatternDraw what, double rms, int row, int column);

}  // namespace rangesim::systemc
