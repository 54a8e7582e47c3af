#include "systemc/tof_lockin/nonideal_stimulus.h"

#include <algorithm>
#include <map>

#include "core/physics.h"
#include "systemc/common/fixed_pattern.h"
#include "systemc/common/optical_blur.h"

namespace rangesim::systemc::lockin {

void add_multipath(const TofLockinConfig& cfg, std::vector<LockinPixelStimulus>& st) {
  const MultipathConfig& mp = cfg.nonideal.multipath;
  if (!mp.on()) return;
  const double extra_s = mp.extra_path_m / phys::kSpeedOfLight_m_per_s;
  for (LockinPixelStimulus& s : st) {
    std::vector<LockinEcho> second{{mp.relative_amplitude * s.signal_A, s.delay_s + extra_s}};
    for (const LockinEcho& e : s.echoes) second.push_back({mp.relative_amplitude * e.signal_A, e.delay_s + extra_s});
    s.echoes.insert(s.echoes.end(), second.begin(), second.end());
  }
}

void apply_blur(const TofLockinConfig& cfg, std::vector<LockinPixelStimulus>& st, int rows, int columns) {
  if (!cfg.nonideal.blur.any()) return;
  const std::vector<BlurTap> taps = blur_taps(cfg.nonideal.blur);
  if (taps.size() == 1) return;  // the identity (a diffraction-limited spot well inside a pixel)
  std::vector<LockinPixelStimulus> out(st.size());
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < columns; ++c) {
      std::map<double, double> by_delay;  // delay -> signal: returns at one delay are one return
      double background = 0;
      for (const BlurTap& t : taps) {
        const LockinPixelStimulus& src = st[static_cast<std::size_t>(blur_source_index(r, c, t, rows, columns))];
        background += t.w * src.background_A;
        by_delay[src.delay_s] += t.w * src.signal_A;
        for (const LockinEcho& e : src.echoes) by_delay[e.delay_s] += t.w * e.signal_A;
      }
      LockinPixelStimulus& o = out[static_cast<std::size_t>(r) * columns + c];
      const LockinPixelStimulus& own = st[static_cast<std::size_t>(r) * columns + c];
      o.background_A = background;
      o.delay_s = own.delay_s;  // the pixel's own surface stays the direct return
      o.signal_A = by_delay[own.delay_s];
      for (const auto& [delay, signal] : by_delay)
        if (delay != own.delay_s && signal > 0) o.echoes.push_back({signal, delay});
    }
  st = std::move(out);
}

void apply_fixed_pattern(const TofLockinConfig& cfg, std::uint64_t seed, std::vector<LockinPixelStimulus>& st, int rows,
                         int columns, int first_row, int first_column) {
  const FixedPatternConfig& fp = cfg.nonideal.fixed_pattern;
  if (!fp.any()) return;
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < columns; ++c) {
      LockinPixelStimulus& s = st[static_cast<std::size_t>(r) * columns + c];
      const int R = first_row + r, C = first_column + c;
      const double g = fixed_gain(seed, FixedPatternDraw::Gain, fp.prnu_fraction, R, C);
      s.signal_A *= g, s.background_A *= g;
      for (LockinEcho& e : s.echoes) e.signal_A *= g;
      s.tap_gain[0] = fixed_gain(seed, FixedPatternDraw::Tap0, fp.tap_mismatch_fraction, R, C);
      s.tap_gain[1] = fixed_gain(seed, FixedPatternDraw::Tap1, fp.tap_mismatch_fraction, R, C);
      // Each FD's own dark current: the spread around the mean, never below no dark current at all.
      const FixedPatternDraw dark_draw[2] = {FixedPatternDraw::Dark, FixedPatternDraw::Dark1};
      for (int k = 0; k < 2; ++k)
        s.dark_extra_A[k] = fp.dsnu_rms > 0 ? std::max(-cfg.noise.dark_current_A,
                                                       fp.dsnu_rms * fixed_pattern_normal(seed, dark_draw[k], R, C))
                                            : 0.0;
    }
}

void apply_nonideal(const TofLockinConfig& cfg, std::vector<LockinPixelStimulus>& st, int rows, int columns) {
  add_multipath(cfg, st);
  apply_blur(cfg, st, rows, columns);
  apply_fixed_pattern(cfg, cfg.nonideal.fixed_pattern.seed, st, rows, columns);
}

}  // namespace rangesim::systemc::lockin
