#include "golden/ls_demodulation/position.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "golden/common/position_noise.h"
#include "golden/common/spot.h"
#include "golden/common/triangulation.h"
#include "golden/ls_demodulation/decision.h"

namespace rangesim::golden {

double demod_range_per_px_m(const LsDemodulationConfig& cfg) {
  return range_per_px_m(cfg.optics, cfg.pixel.pitch_m, cfg.optics.distance_m);
}

namespace {

using Vec = std::vector<double>;
using Mat = std::vector<Vec>;

// One frame of K decisions at one spot position, over the frame-common offset o: the mixture
// moments of the frame estimate given a detection, and what the trial's N_p frames need.
struct FrameMix {
  double pd = 0, m1 = 0, m2 = 0, vk = 0;  // weighted by P(o) P(detect | o) [P(keep | o)]
  double none = 0;                        // E_o[P(keep, no detection | o)]
  double keep = 0;                        // E_o[P(keep | o)]: no outlier in any decision
  void add(double w, const PositionMoments& m, int K, double keep_o) {
    const double keep_k = std::pow(keep_o, K);
    keep += w * keep_k;
    none += w * keep_k * std::exp(K * std::log1p(-std::min(m.p_detect, 1.0)));
    if (!(m.p_detect > 0)) return;
    const double wd = w * keep_k * m.p_detect;
    // K decisions: expected number of detections given at least one.
    const double any = -std::expm1(K * std::log1p(-std::min(m.p_detect, 1 - 1e-16)));
    const double k_eff = std::max(1.0, K * m.p_detect / std::max(any, 1e-300));
    pd += wd, m1 += wd * m.mean_px, m2 += wd * m.mean_px * m.mean_px, vk += wd * m.var_px2 / k_eff;
  }
};

// Sums over positions of the trial's P(detect), and of the errors weighted by it.
struct PositionSums {
  double p = 0, w = 0, b2 = 0, var = 0, e2 = 0, worst = 0;
  int used = 0;
  // N_p independent frames: the trial detects (and keeps) unless every frame misses (or one has an
  // outlier): P = keep^N_p - none^N_p.
  void add(const FrameMix& f, double x0, int frames) {
    const double n = frames;
    // The Gauss-Hermite weights sum to 1 only to rounding: keep the probabilities in [0, 1].
    const double keep = std::clamp(f.keep, 0.0, 1.0), none = std::clamp(f.none, 0.0, keep);
    const double p_trial = std::pow(keep, n) - std::pow(none, n);
    p += p_trial;
    if (!(f.pd > 1e-9)) return;
    const double mean_x = f.m1 / f.pd, b = mean_x - x0;
    const double v = std::max(0.0, f.m2 / f.pd - mean_x * mean_x) + f.vk / f.pd;
    w += p_trial, b2 += p_trial * b * b, var += p_trial * v, e2 += p_trial * (b * b + v / n);
    worst = std::max(worst, std::fabs(b) + 3 * std::sqrt(v / n));
    ++used;
  }
  double rms(double s) const { return w > 0 ? std::sqrt(s / w) : std::nan(""); }
};

}  // namespace

DemodAccuracy position_accuracy(const LsDemodulationConfig& cfg, double signal_A, double background_A, int K,
                                int frames) {
  DemodAccuracy r;
  const int P = std::max(1, cfg.grid.subpixel_points), cols = cfg.pixel.columns, c = cols / 2;
  const double vcmp = cfg.comparator.threshold_V;
  // Pixels farther than R from the spot see g < 1e-12 of the signal: background-only class.
  const int R = static_cast<int>(std::ceil(spot_half_width_px(cfg.spot, 1e-12))) + 1;
  const PixelDecision bg = pixel_decision(cfg, 0.0, background_A);
  const GaussNodes g = gauss_nodes(bg.sigma_common_V);
  // Background pixels join the estimate only if one of them may activate at all; then the frames
  // with an outlier (an activation outside the spot's pixels, golden/common/spot.h) are split off.
  bool whole_row = false;
  for (int i = 0; i < g.n; ++i)
    whole_row |= activation(bg.mean_V + g.offset_V[i], vcmp, bg.sigma_independent_V).p > 1e-15;
  const int lo = whole_row ? 0 : std::max(0, c - R), hi = whole_row ? cols - 1 : std::min(cols - 1, c + R);
  const int W = hi - lo + 1;

  Vec x(W), mean(W), sig(W);
  Mat C(W, Vec(3)), S(W, Vec(3));
  for (int j = 0; j < W; ++j) x[j] = lo + j - c;
  PositionSums all, clean;
  double sum_out = 0;
  r.p_detect_min = 1;
  for (int p = 0; p < P; ++p) {
    const double x0 = -0.5 + (p + 0.5) / P;  // spot centre relative to pixel c
    for (int j = 0; j < W; ++j) {
      if (std::fabs(x[j] - x0) > R) {
        mean[j] = bg.mean_V, sig[j] = bg.sigma_independent_V;
        continue;
      }
      const PixelDecision d = pixel_decision(cfg, signal_A * spot_profile(cfg.spot, x[j] - x0), background_A);
      mean[j] = d.mean_V, sig[j] = d.sigma_independent_V;
    }
    // The spot's pixels in the window: [a, b].
    const ColumnSpan spot = spot_window(cfg.spot, c + x0, cols);
    const int a = std::max(spot.first, lo) - lo, b = std::min(spot.last, hi) - lo;
    const bool split = whole_row && (a > 0 || b < W - 1);  // else no pixel outside may activate (< 1e-15)
    FrameMix fa, fc;
    double pd_one = 0;
    for (int i = 0; i < g.n; ++i) {
      double log_keep = 0;  // log P(no pixel outside the spot's activates in one decision | o)
      for (int j = 0; j < W; ++j) {
        const Tail t = activation(mean[j] + g.offset_V[i], vcmp, sig[j]);
        C[j] = {0.0, t.p, 1.0};
        S[j] = {1.0, t.q, 0.0};
        if (j < a || j > b) log_keep += std::log(t.q);
      }
      const PositionMoments m = edge_centre_moments(x, C, S, 1);
      pd_one += g.weight[i] * m.p_detect;
      fa.add(g.weight[i], m, K, 1.0);
      if (!split) continue;
      PositionMoments mc;  // the spot's pixels alone: the estimate given no outlier
      if (a <= b)
        mc = edge_centre_moments(Vec(x.begin() + a, x.begin() + b + 1), Mat(C.begin() + a, C.begin() + b + 1),
                                 Mat(S.begin() + a, S.begin() + b + 1), 1);
      fc.add(g.weight[i], mc, K, std::exp(log_keep));
    }
    if (!split) fc = fa;
    r.p_detect_min = std::min(r.p_detect_min, pd_one);
    all.add(fa, x0, frames);
    clean.add(fc, x0, frames);
    sum_out += 1 - std::pow(std::clamp(fc.keep, 0.0, 1.0), frames);
  }
  r.detected_fraction = static_cast<double>(all.used) / P;
  r.p_detect = all.p / P;
  r.p_outlier = std::clamp(sum_out / P, 0.0, 1.0);
  r.worst_error_px = all.worst;
  if (all.used == 0 || !(all.w > 0)) {
    r.accuracy_px = r.bias_rms_px = r.noise_std_px = r.accuracy_m = r.accuracy_clean_px = r.accuracy_clean_m =
        std::nan("");
    return r;
  }
  r.bias_rms_px = all.rms(all.b2);
  r.noise_std_px = all.rms(all.var);
  r.accuracy_px = all.rms(all.e2);
  r.accuracy_clean_px = clean.rms(clean.e2);
  r.accuracy_m = r.accuracy_px * demod_range_per_px_m(cfg);
  r.accuracy_clean_m = r.accuracy_clean_px * demod_range_per_px_m(cfg);
  return r;
}

}  // namespace rangesim::golden
