#include "golden/ls_demodulation/position.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "golden/ls_demodulation/decision.h"
#include "golden/common/position_noise.h"
#include "golden/common/spot.h"
#include "golden/common/triangulation.h"

namespace rangesim::golden {

double demod_range_per_px_m(const LsDemodulationConfig& cfg) {
  return range_per_px_m(cfg.optics, cfg.pixel.pitch_m, cfg.optics.distance_m);
}

DemodAccuracy position_accuracy(const LsDemodulationConfig& cfg, double signal_A, double background_A, int K,
                                int frames) {
  DemodAccuracy r;
  const int P = std::max(1, cfg.grid.subpixel_points), cols = cfg.pixel.columns, c = cols / 2;
  const double vcmp = cfg.comparator.threshold_V;
  // Pixels farther than R from the spot see g < 1e-12 of the signal: background-only class.
  const int R = static_cast<int>(std::ceil(spot_half_width_px(cfg.spot, 1e-12))) + 1;
  const PixelDecision bg = pixel_decision(cfg, 0.0, background_A);
  const GaussNodes g = gauss_nodes(bg.sigma_common_V);
  // Background pixels join the estimate only if one of them may activate at all.
  bool whole_row = false;
  for (int i = 0; i < g.n; ++i)
    whole_row |= activation(bg.out.diff_V + g.offset_V[i], vcmp, bg.sigma_independent_V).p > 1e-15;
  const int lo = whole_row ? 0 : std::max(0, c - R), hi = whole_row ? cols - 1 : std::min(cols - 1, c + R);
  const int W = hi - lo + 1;

  std::vector<double> x(W), mean(W), sig(W);
  std::vector<std::vector<double>> C(W, std::vector<double>(3)), S(W, std::vector<double>(3));
  for (int j = 0; j < W; ++j) x[j] = lo + j - c;
  double sum_b2 = 0, sum_var = 0, sum_e2 = 0;
  int used = 0;
  r.p_detect_min = 1;
  for (int p = 0; p < P; ++p) {
    const double x0 = -0.5 + (p + 0.5) / P;  // spot centre relative to pixel c
    for (int j = 0; j < W; ++j) {
      if (std::fabs(x[j] - x0) > R) {
        mean[j] = bg.out.diff_V, sig[j] = bg.sigma_independent_V;
        continue;
      }
      const PixelDecision d = pixel_decision(cfg, signal_A * spot_profile(cfg.spot, x[j] - x0), background_A);
      mean[j] = d.out.diff_V, sig[j] = d.sigma_independent_V;
    }
    double pd = 0, m1 = 0, m2 = 0, vk = 0;  // weighted by P(o) P(detect | o)
    for (int i = 0; i < g.n; ++i) {
      for (int j = 0; j < W; ++j) {
        const Tail t = activation(mean[j] + g.offset_V[i], vcmp, sig[j]);
        C[j] = {0.0, t.p, 1.0};
        S[j] = {1.0, t.q, 0.0};
      }
      const PositionMoments m = edge_centre_moments(x, C, S, 1);
      if (!(m.p_detect > 0)) continue;
      const double w = g.weight[i] * m.p_detect;
      // K decisions: expected number of detections given at least one.
      const double any = -std::expm1(K * std::log1p(-std::min(m.p_detect, 1 - 1e-16)));
      const double k_eff = std::max(1.0, K * m.p_detect / std::max(any, 1e-300));
      pd += w;
      m1 += w * m.mean_px;
      m2 += w * m.mean_px * m.mean_px;
      vk += w * m.var_px2 / k_eff;
    }
    r.p_detect_min = std::min(r.p_detect_min, pd);
    if (!(pd > 1e-9)) continue;
    const double mean_x = m1 / pd, b = mean_x - x0;
    const double var = std::max(0.0, m2 / pd - mean_x * mean_x) + vk / pd;
    sum_b2 += b * b;
    sum_var += var;
    sum_e2 += b * b + var / frames;
    r.worst_error_px = std::max(r.worst_error_px, std::fabs(b) + 3 * std::sqrt(var / frames));
    ++used;
  }
  r.detected_fraction = static_cast<double>(used) / P;
  if (used == 0) {
    r.accuracy_px = r.bias_rms_px = r.noise_std_px = r.accuracy_m = std::nan("");
    return r;
  }
  r.bias_rms_px = std::sqrt(sum_b2 / used);
  r.noise_std_px = std::sqrt(sum_var / used);
  r.accuracy_px = std::sqrt(sum_e2 / used);
  r.accuracy_m = r.accuracy_px * demod_range_per_px_m(cfg);
  return r;
}

}  // namespace rangesim::golden
