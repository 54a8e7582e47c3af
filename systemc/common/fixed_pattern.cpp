#include "systemc/common/fixed_pattern.h"

#include <algorithm>

#include "systemc/common/random_stream.h"

namespace rangesim::systemc {

namespace {
// Frame words of the fixed-pattern streams: far above any frame a run reaches (2^62 + what),
// so a fixed-pattern stream never coincides with a frame's noise stream.
constexpr std::uint64_t kFixedPatternFrame = std::uint64_t{1} << 62;
}  // namespace

double fixed_pattern_normal(std::uint64_t seed, FixedPatternDraw what, int row, int column) {
  pcg32 rng = pixel_stream(pixel_stream_key(seed, kFixedPatternFrame + static_cast<std::uint64_t>(what),
                                            static_cast<std::uint32_t>(row), static_cast<std::uint32_t>(column)));
  return standard_normal(rng);
}

double fixed_gain(std::uint64_t seed, FixedPatternDraw what, double rms, int row, int column) {
  if (!(rms > 0)) return 1.0;
  return std::max(0.0, 1.0 + rms * fixed_pattern_normal(seed, what, row, column));
}

}  // namespace rangesim::systemc
