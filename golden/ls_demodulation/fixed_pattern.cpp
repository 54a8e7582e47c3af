#include "golden/ls_demodulation/fixed_pattern.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "golden/common/position_noise.h"
#include "golden/common/spot.h"
#include "golden/ls_demodulation/decision.h"

namespace rangesim::golden {

namespace {

// The spot pixels of a row and their one-decision statistics: mean of D over chips, the temporal
// noise alone and the chip's part (comparator offset, PRNU, DSNU) apart.
struct RowStats {
  std::vector<double> x, mean, sig, chip;
};

RowStats row_stats(const LsDemodulationConfig& cfg, double signal_A, double background_A, double x0, int R) {
  RowStats r;
  for (int j = -R; j <= R; ++j) {
    const PixelDecision d = pixel_decision(cfg, signal_A * spot_profile(cfg.spot, j - x0), background_A);
    const double temporal2 = d.sigma_independent_V * d.sigma_independent_V - d.sigma_chip_V * d.sigma_chip_V;
    r.x.push_back(j), r.mean.push_back(d.mean_V), r.sig.push_back(std::sqrt(std::max(0.0, temporal2)));
    r.chip.push_back(d.sigma_chip_V);
  }
  return r;
}

// E[centre | detect], averaged over the frame-common read offset as position_accuracy does.
double frame_mean_px(const LsDemodulationConfig& cfg, const RowStats& r, const GaussNodes& g) {
  const std::size_t W = r.x.size();
  std::vector<std::vector<double>> C(W, std::vector<double>(3)), S(W, std::vector<double>(3));
  double pd = 0, m1 = 0;
  for (int i = 0; i < g.n; ++i) {
    for (std::size_t j = 0; j < W; ++j) {
      const Tail t = activation(r.mean[j] + g.offset_V[i], cfg.comparator.threshold_V, r.sig[j]);
      C[j] = {0.0, t.p, 1.0};
      S[j] = {1.0, t.q, 0.0};
    }
    const PositionMoments m = edge_centre_moments(r.x, C, S, 1);
    pd += g.weight[i] * m.p_detect;
    m1 += g.weight[i] * m.p_detect * m.mean_px;
  }
  return pd > 0 ? m1 / pd : 0.0;
}

// Var over chips of E[centre | the chip's pattern], linearised in each pixel's chip offset of D with
// secants over +- its rms sigma_j (the response of a pixel near threshold is smooth on the scale of
// its temporal noise), averaged over spot positions across a pixel.
double chip_variance_px2(const LsDemodulationConfig& cfg, double signal_A, double background_A) {
  const int P = std::max(1, cfg.grid.subpixel_points);
  const int R = static_cast<int>(std::ceil(spot_half_width_px(cfg.spot, 1e-12))) + 1;
  const GaussNodes g = gauss_nodes(cfg.noise.read_noise_V);
  double sum = 0;
  for (int p = 0; p < P; ++p) {
    const double x0 = -0.5 + (p + 0.5) / P;
    RowStats r = row_stats(cfg, signal_A, background_A, x0, R);
    double v = 0;
    for (std::size_t j = 0; j < r.x.size(); ++j) {
      const double mu = r.mean[j], s = r.chip[j];
      if (!(s > 0)) continue;
      r.mean[j] = mu + s;
      const double up = frame_mean_px(cfg, r, g);
      r.mean[j] = mu - s;
      const double down = frame_mean_px(cfg, r, g);
      r.mean[j] = mu;
      v += 0.25 * (up - down) * (up - down);  // (slope sigma_j)^2 with slope = (up - down) / (2 sigma_j)
    }
    sum += v;
  }
  return sum / P;
}

}  // namespace

DemodAccuracy accuracy_with_fixed_offsets(const LsDemodulationConfig& cfg, double signal_A, double background_A,
                                          int detections, int frames) {
  const FixedPatternConfig& fp = cfg.fixed_pattern;
  const bool chip = fp.comparator_offset_rms_V > 0 || fp.prnu_fraction > 0 || fp.dsnu_rms > 0;
  if (!chip || frames <= 1) return position_accuracy(cfg, signal_A, background_A, detections, frames);
  // One frame: the pattern as independent draws per pixel (pixel_decision). Over frames only the
  // part of that variance that is the chip's, V_fp, stays: accuracy^2 = b^2 + V_fp + (V_1 - V_fp) / N_p.
  DemodAccuracy a = position_accuracy(cfg, signal_A, background_A, detections, 1);
  if (!std::isfinite(a.accuracy_px)) return a;
  const double v1 = a.noise_std_px * a.noise_std_px;
  const double v_fp = std::min(v1, chip_variance_px2(cfg, signal_A, background_A));
  const double n = static_cast<double>(frames);
  a.accuracy_px = std::sqrt(a.bias_rms_px * a.bias_rms_px + v_fp + (v1 - v_fp) / n);
  a.bias_rms_px = std::sqrt(a.bias_rms_px * a.bias_rms_px + v_fp);  // what averaging cannot remove
  a.worst_error_px = a.bias_rms_px + 3 * std::sqrt((v1 - v_fp) / n);
  a.accuracy_m = a.accuracy_px * demod_range_per_px_m(cfg);
  // The trials' detections and outliers are correlated through the chip over the frames: their
  // probabilities as of independent frames would be wrong, so they are left undefined here, and
  // so is the split of the accuracy (the Monte Carlo is compared on the total).
  a.p_detect = a.p_outlier = a.accuracy_clean_px = a.accuracy_clean_m = std::nan("");
  return a;
}

}  // namespace rangesim::golden
