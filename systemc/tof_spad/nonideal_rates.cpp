#include "systemc/tof_spad/nonideal_rates.h"

#include <algorithm>

#include "systemc/common/fixed_pattern.h"

namespace rangesim::systemc::spad {

PixelRates with_fixed_pattern(const TofSpadConfig& cfg, std::uint64_t seed, PixelRates r, int row, int column) {
  const FixedPatternConfig& fp = cfg.fixed_pattern;
  if (!fp.any()) return r;
  const double g = fixed_gain(seed, FixedPatternDraw::Gain, fp.prnu_fraction, row, column);
  r.signal_Hz *= g, r.background_Hz *= g;
  if (fp.dsnu_rms > 0)
    r.dark_extra_Hz = std::max(-cfg.spad.dark_count_rate_Hz,
                               fp.dsnu_rms * fixed_pattern_normal(seed, FixedPatternDraw::Dark, row, column));
  return r;
}

}  // namespace rangesim::systemc::spad
