#include "systemc/ls_demodulation/nonideal_stimulus.h"

#include <algorithm>

#include "systemc/common/fixed_pattern.h"
#include "systemc/common/optical_blur.h"

namespace rangesim::systemc {

void apply_demod_blur(const LsDemodulationConfig& cfg, DemodStimulus& s) {
  if (!cfg.blur.any()) return;
  const std::vector<BlurTap> taps = blur_taps(cfg.blur);
  if (taps.size() == 1) return;  // the identity
  const int R = cfg.pixel.rows, C = cfg.pixel.columns;
  s.beam_A = blur_image(s.beam_A, R, C, taps);
  s.background_A = blur_image(s.background_A, R, C, taps);
}

void apply_demod_fixed_pattern(const LsDemodulationConfig& cfg, DemodStimulus& s) {
  apply_demod_fixed_pattern(cfg, s, cfg.fixed_pattern.seed);
}

void apply_demod_fixed_pattern(const LsDemodulationConfig& cfg, DemodStimulus& s, std::uint64_t seed) {
  const FixedPatternConfig& fp = cfg.fixed_pattern;
  if (!fp.any()) return;
  const int R = static_cast<int>(s.beam_A.size()) / cfg.pixel.columns, C = cfg.pixel.columns;
  if (fp.comparator_offset_rms_V > 0) s.comparator_offset_V.assign(static_cast<std::size_t>(R) * C, 0.0);
  for (int r = 0; r < R; ++r)
    for (int c = 0; c < C; ++c) {
      const std::size_t i = static_cast<std::size_t>(r) * C + c;
      const double g = fixed_gain(seed, FixedPatternDraw::Gain, fp.prnu_fraction, r, c);
      s.beam_A[i] *= g;
      // The pixel's dark current differs from the mean by the DSNU draw (never below none at all).
      const double dark = fp.dsnu_rms > 0 ? fp.dsnu_rms * fixed_pattern_normal(seed, FixedPatternDraw::Dark, r, c) : 0;
      s.background_A[i] = std::max(-cfg.noise.dark_current_A, s.background_A[i] * g + dark);
      if (!s.comparator_offset_V.empty())
        s.comparator_offset_V[i] =
            fp.comparator_offset_rms_V * fixed_pattern_normal(seed, FixedPatternDraw::ComparatorOffset, r, c);
    }
}

}  // namespace rangesim::systemc
