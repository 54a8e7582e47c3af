#include "golden/ls_demodulation/decision.h"

#include <algorithm>
#include <cmath>

#include "golden/common/threshold.h"

namespace rangesim::golden {

const char* to_string(DemodDetect d) {
  switch (d) {
    case DemodDetect::Detectable: return "detectable";
    case DemodDetect::BelowThreshold: return "below_threshold";
    case DemodDetect::Saturated: return "saturated";
    case DemodDetect::BackgroundActivation: return "background_activation";
  }
  return "?";
}

PixelDecision pixel_decision(const LsDemodulationConfig& cfg, double beam_A, double background_A) {
  PixelDecision d;
  d.out = correlate_periodic(cfg, pixel_segments(cfg, beam_A, background_A), cfg.correlator.cycles);
  // Per-decision offset and the comparator's fixed offset: in one decision both are independent
  // per pixel (the fixed one does not average over decisions and frames: fixed_pattern.h).
  const double fpn = std::hypot(cfg.noise.fixed_pattern_rms_V, cfg.fixed_pattern.comparator_offset_rms_V);
  d.sigma_independent_V = std::sqrt(d.out.shot_var_V2 + ktc_variance_V2(cfg) + fpn * fpn);
  d.sigma_common_V = cfg.noise.read_noise_V;
  return d;
}

Tail activation(double mean_V, double threshold_V, double sigma_V) {
  if (!(sigma_V > 0)) return mean_V >= threshold_V ? Tail{1, 0} : Tail{0, 1};
  const double z = (mean_V - threshold_V) / (sigma_V * std::sqrt(2.0));
  return {0.5 * std::erfc(-z), 0.5 * std::erfc(z)};
}

GaussNodes gauss_nodes(double sigma_V) {
  GaussNodes g;
  if (!(sigma_V > 0)) {
    g.n = 1;
    g.offset_V[0] = 0;
    g.weight[0] = 1;
    return g;
  }
  // Physicists' Hermite nodes/weights (n = 9); o = sqrt(2) sigma x, weight w / sqrt(pi).
  static const double x[9] = {-3.190993201781528, -2.266580584531843, -1.468553289216668, -0.7235510187528376, 0.0,
                              0.7235510187528376, 1.468553289216668,  2.266580584531843,  3.190993201781528};
  static const double w[9] = {3.96069772632644e-5,  4.943624275536947e-3, 8.847452739437657e-2,
                              0.4326515590025558,   0.7202352156060510,   0.4326515590025558,
                              8.847452739437657e-2, 4.943624275536947e-3, 3.96069772632644e-5};
  g.n = 9;
  for (int i = 0; i < 9; ++i) {
    g.offset_V[i] = std::sqrt(2.0) * sigma_V * x[i];
    g.weight[i] = w[i] / std::sqrt(M_PI);
  }
  return g;
}

Classification classify(const LsDemodulationConfig& cfg, double signal_A, double background_A) {
  Classification c;
  const double vcmp = cfg.comparator.threshold_V, vsat = cfg.correlator.saturation_voltage_V;
  c.background = pixel_decision(cfg, 0.0, background_A);
  c.peak = pixel_decision(cfg, signal_A, background_A);
  // Row false activation: E_o[1 - (1 - p(o))^M] over the frame-common offset.
  const GaussNodes g = gauss_nodes(c.background.sigma_common_V);
  const double M = cfg.pixel.columns;
  for (int i = 0; i < g.n; ++i) {
    const Tail t = activation(c.background.out.diff_V + g.offset_V[i], vcmp, c.background.sigma_independent_V);
    c.row_false_activation += g.weight[i] * -std::expm1(M * std::log1p(-std::min(t.p, 1 - 1e-300)));
  }
  // The Gauss-Hermite weights sum to 1 only to rounding: keep the probability in [0, 1].
  c.row_false_activation = std::clamp(c.row_false_activation, 0.0, 1.0);
  if (c.background.out.peak_abs_V > vsat)
    c.detect = DemodDetect::Saturated;
  else if (reaches_threshold(c.background.out.diff_V, vcmp) ||
           c.row_false_activation > cfg.comparator.false_activation_max)
    c.detect = DemodDetect::BackgroundActivation;
  else if (c.peak.out.peak_abs_V > vsat)
    c.detect = DemodDetect::Saturated;
  else if (below_threshold(c.peak.out.diff_V, vcmp))
    c.detect = DemodDetect::BelowThreshold;
  else
    c.detect = DemodDetect::Detectable;
  return c;
}

}  // namespace rangesim::golden
