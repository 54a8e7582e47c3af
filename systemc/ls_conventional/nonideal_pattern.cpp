#include "systemc/ls_conventional/nonideal_pattern.h"

#include <algorithm>
#include <cmath>

#include "golden/common/pixel.h"
#include "golden/common/spot.h"
#include "systemc/common/fixed_pattern.h"

namespace rangesim::systemc {

namespace {
// A source pixel's spot swing below this share of its row's peak is not spread (1.5 V x 1e-16:
// far below any noise, and the spread keeps every weight's sum within 1e-12 of 1 anyway).
constexpr double kSpreadLevel = 1e-16;
}  // namespace

PixelPattern make_pixel_pattern(const LsConventionalConfig& cfg, std::uint64_t seed) {
  const FixedPatternConfig& f = cfg.fixed_pattern;
  const int R = cfg.pixel.rows, C = cfg.pixel.columns;
  const std::size_t n = static_cast<std::size_t>(R) * static_cast<std::size_t>(C);
  PixelPattern p;
  if (f.prnu_fraction > 0) p.gain.resize(n);
  if (f.dsnu_rms > 0) p.dark_V.resize(n);
  if (f.comparator_offset_rms_V > 0) p.offset_V.resize(n), p.max_offset_V.assign(static_cast<std::size_t>(R), -1e300);
  const PixelConfig& px = cfg.pixel;
  for (int r = 0; r < R; ++r)
    for (int c = 0; c < C; ++c) {
      const std::size_t x = static_cast<std::size_t>(r) * static_cast<std::size_t>(C) + static_cast<std::size_t>(c);
      if (!p.gain.empty()) p.gain[x] = fixed_gain(seed, FixedPatternDraw::Gain, f.prnu_fraction, r, c);
      if (!p.dark_V.empty()) {
        const double I = px.dark_current_A + f.dsnu_rms * fixed_pattern_normal(seed, FixedPatternDraw::Dark, r, c);
        p.dark_V[x] = golden::voltage_from_current_V(std::max(0.0, I), px.integration_time_s, px.pd_capacitance_F);
      }
      if (!p.offset_V.empty()) {
        const double o =
            f.comparator_offset_rms_V * fixed_pattern_normal(seed, FixedPatternDraw::ComparatorOffset, r, c);
        p.offset_V[x] = o;
        p.max_offset_V[static_cast<std::size_t>(r)] = std::max(p.max_offset_V[static_cast<std::size_t>(r)], o);
      }
    }
  return p;
}

std::vector<BlurTap> ls_conventional_blur_taps(const LsConventionalConfig& cfg) {
  if (!cfg.blur.any()) return {};
  std::vector<BlurTap> taps = blur_taps(cfg.blur);
  if (taps.size() == 1 && taps[0].dr == 0 && taps[0].dc == 0) return {};
  return taps;
}

void spread_spot(const LsConventionalConfig& cfg, const std::vector<BlurTap>& taps, FrameStimulus& s) {
  const int R = cfg.pixel.rows, C = cfg.pixel.columns;
  s.signal_px_V.assign(static_cast<std::size_t>(R) * static_cast<std::size_t>(C), 0.0);
  int reach_r = 0, reach_c = 0;
  for (const BlurTap& t : taps)
    reach_r = std::max(reach_r, std::abs(t.dr)), reach_c = std::max(reach_c, std::abs(t.dc));
  // Each source row's spot swings over its columns lo..hi (hi < lo: no spot).
  const double h = golden::spot_half_width_px(cfg.spot, kSpreadLevel);
  std::vector<int> lo(static_cast<std::size_t>(R), 0), hi(static_cast<std::size_t>(R), -1);
  std::vector<std::vector<double>> src(static_cast<std::size_t>(R));
  const int first = std::clamp(s.first_row, 0, R);
  const int last = s.row_count < 0 ? R - 1 : std::min(R - 1, first + s.row_count - 1);
  for (int r = std::max(0, first - reach_r); r <= std::min(R - 1, last + reach_r); ++r) {
    const RowIllumination& in = s.rows[static_cast<std::size_t>(r)];
    if (!(in.signal_V > 0)) continue;
    const std::size_t u = static_cast<std::size_t>(r);
    lo[u] = std::max(0, static_cast<int>(std::ceil(in.centre_px - h)));
    hi[u] = std::min(C - 1, static_cast<int>(std::floor(in.centre_px + h)));
    for (int c = lo[u]; c <= hi[u]; ++c)
      src[u].push_back(in.signal_V * golden::spot_profile(cfg.spot, c - in.centre_px));
  }
  for (int r = first; r <= last; ++r) {
    // The receiving columns: those a tap reaches from a source row's spot (edges clamp, as blur_image).
    int a = C, b = -1;
    for (int q = std::max(0, r - reach_r); q <= std::min(R - 1, r + reach_r); ++q)
      if (hi[static_cast<std::size_t>(q)] >= lo[static_cast<std::size_t>(q)])
        a = std::min(a, lo[static_cast<std::size_t>(q)] - reach_c),
        b = std::max(b, hi[static_cast<std::size_t>(q)] + reach_c);
    a = std::max(a, 0), b = std::min(b, C - 1);
    double* out = s.signal_px_V.data() + static_cast<std::size_t>(r) * static_cast<std::size_t>(C);
    for (int c = a; c <= b; ++c) {
      double v = 0;
      for (const BlurTap& t : taps) {
        const int q = std::clamp(r - t.dr, 0, R - 1), cc = std::clamp(c - t.dc, 0, C - 1);
        const std::size_t u = static_cast<std::size_t>(q);
        if (cc >= lo[u] && cc <= hi[u]) v += t.w * src[u][static_cast<std::size_t>(cc - lo[u])];
      }
      out[c] = v;
    }
  }
}

}  // namespace rangesim::systemc
