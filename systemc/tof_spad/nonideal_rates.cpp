#include "systemc/tof_spad/nonideal_rates.h"

#include <algorithm>
#include <map>

#include "core/physics.h"
#include "systemc/common/fixed_pattern.h"
#include "systemc/common/optical_blur.h"

namespace rangesim::systemc::spad {

PixelRates with_fixed_pattern(const TofSpadConfig& cfg, std::uint64_t seed, PixelRates r, int row, int column) {
  const FixedPatternConfig& fp = cfg.fixed_pattern;
  if (!fp.any()) return r;
  const double g = fixed_gain(seed, FixedPatternDraw::Gain, fp.prnu_fraction, row, column);
  r.signal_Hz *= g, r.background_Hz *= g;
  for (SpadEcho& e : r.echoes) e.signal_Hz *= g;
  if (fp.dsnu_rms > 0)
    r.dark_extra_Hz = std::max(-cfg.spad.dark_count_rate_Hz,
                               fp.dsnu_rms * fixed_pattern_normal(seed, FixedPatternDraw::Dark, row, column));
  return r;
}

PixelRates with_multipath(const TofSpadConfig& cfg, PixelRates r) {
  const MultipathConfig& mp = cfg.multipath;
  if (!mp.on()) return r;
  const double extra_s = mp.extra_path_m / phys::kSpeedOfLight_m_per_s, a = mp.relative_amplitude;
  std::vector<SpadEcho> second{{a * r.signal_Hz, r.round_trip_s + extra_s}};
  for (const SpadEcho& e : r.echoes) second.push_back({a * e.signal_Hz, e.round_trip_s + extra_s});
  r.echoes.insert(r.echoes.end(), second.begin(), second.end());
  return r;
}

namespace {

// The pixel's light through the point spread and crosstalk: the background and the echoes of the
// source pixels weighted by the taps; the pixel's own delay stays the direct return.
PixelRates blurred(const TofSpadConfig& cfg, const RateSource& scene, const std::vector<BlurTap>& taps, int r, int c,
                   int rows, int columns) {
  const PixelRates own = with_multipath(cfg, scene(r, c));
  std::map<double, double> by_delay;  // delay -> signal: returns at one delay are one return
  double background = 0;
  for (const BlurTap& t : taps) {
    const int i = blur_source_index(r, c, t, rows, columns);
    const PixelRates src = with_multipath(cfg, scene(i / columns, i % columns));
    background += t.w * src.background_Hz;
    by_delay[src.round_trip_s] += t.w * src.signal_Hz;
    for (const SpadEcho& e : src.echoes) by_delay[e.round_trip_s] += t.w * e.signal_Hz;
  }
  PixelRates out = own;
  out.background_Hz = background;
  out.signal_Hz = by_delay[own.round_trip_s];
  out.echoes.clear();
  for (const auto& [delay, signal] : by_delay)
    if (delay != own.round_trip_s && signal > 0) out.echoes.push_back({signal, delay});
  return out;
}

}  // namespace

RateSource chip_rates(const TofSpadConfig& cfg, std::uint64_t seed, RateSource scene, int rows, int columns) {
  std::vector<BlurTap> taps = cfg.blur.any() ? blur_taps(cfg.blur) : std::vector<BlurTap>{};
  if (taps.size() <= 1) taps.clear();  // the identity (a diffraction-limited spot well inside a pixel)
  return [cfg, seed, scene = std::move(scene), taps = std::move(taps), rows, columns](int r, int c) {
    const PixelRates light =
        taps.empty() ? with_multipath(cfg, scene(r, c)) : blurred(cfg, scene, taps, r, c, rows, columns);
    return with_fixed_pattern(cfg, seed, light, r, c);
  };
}

}  // namespace rangesim::systemc::spad
