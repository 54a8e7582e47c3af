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

namespace {

// D of a pixel of this chip with gain G (PRNU) and dark-current offset d (DSNU), as the clock-level
// model's fixed pattern applies them (systemc/ls_demodulation/nonideal_stimulus.cpp): the beam and
// background scaled by G, the background moved by d, never below no dark current at all.
CorrelatorOutput chip_pixel(const LsDemodulationConfig& cfg, double beam_A, double background_A, double G, double d) {
  const double bg = std::max(-cfg.noise.dark_current_A, background_A * G + d);
  return correlate_periodic(cfg, pixel_segments(cfg, beam_A * G, bg), cfg.correlator.cycles);
}

struct ChipSpread {
  double mean_V = 0, var_V2 = 0;  // of D over chips
  double shot_var_V2 = 0;         // E over chips of the shot-noise variance
};

// Gauss-Hermite rules for E[f(z)], z ~ N(0, 1): n points integrate polynomials of degree 2n - 1.
struct Rule {
  int n;
  double z[5], w[5];
};
constexpr Rule kRule1 = {1, {0.0}, {1.0}};
constexpr Rule kRule3 = {3, {0.0, -1.7320508075688772, 1.7320508075688772}, {2.0 / 3, 1.0 / 6, 1.0 / 6}};
constexpr Rule kRule5 = {
    5,
    {0.0, -1.3556261799742657, 1.3556261799742657, -2.8569700138728056, 2.8569700138728056},
    {0.53333333333333333, 0.22207592200561265, 0.22207592200561265, 0.011257411327720691, 0.011257411327720691}};

// Mean and variance of D over the PRNU and DSNU draws z, z' ~ N(0, 1), by a product Gauss-Hermite
// rule: 5 points in z (the log stage compresses a strong beam: E[D] exact for D up to degree 9 in
// z, Var up to degree 4), 3 in z' (D moves little and smoothly with the dark current: up to degree
// 5 and 2).
ChipSpread chip_spread(const LsDemodulationConfig& cfg, double beam_A, double background_A,
                       const CorrelatorOutput& nominal) {
  const double p = cfg.fixed_pattern.prnu_fraction, sd = cfg.fixed_pattern.dsnu_rms;
  if (!(p > 0) && !(sd > 0)) return {nominal.diff_V, 0.0, nominal.shot_var_V2};
  const Rule& rg = p > 0 ? kRule5 : kRule1;
  const Rule& rd = sd > 0 ? kRule3 : kRule1;
  double m1 = 0, m2 = 0, shot = 0;
  for (int i = 0; i < rg.n; ++i)
    for (int j = 0; j < rd.n; ++j) {
      const double wt = rg.w[i] * rd.w[j];
      const CorrelatorOutput o =
          i == 0 && j == 0 ? nominal
                           : chip_pixel(cfg, beam_A, background_A, std::max(0.0, 1 + p * rg.z[i]), sd * rd.z[j]);
      m1 += wt * o.diff_V, m2 += wt * o.diff_V * o.diff_V, shot += wt * o.shot_var_V2;
    }
  return {m1, std::max(0.0, m2 - m1 * m1), shot};
}

}  // namespace

PixelDecision pixel_decision(const LsDemodulationConfig& cfg, double beam_A, double background_A) {
  PixelDecision d;
  d.out = correlate_periodic(cfg, pixel_segments(cfg, beam_A, background_A), cfg.correlator.cycles);
  const ChipSpread chip = chip_spread(cfg, beam_A, background_A, d.out);
  d.mean_V = chip.mean_V;
  // The chip's part: the comparator's fixed offset and the spread of D from PRNU and DSNU. In one
  // decision it is independent per pixel like the rest (it does not average over decisions and
  // frames: fixed_pattern.h). noise.fixed_pattern_rms_V stays a per-decision offset.
  const double cmp = cfg.fixed_pattern.comparator_offset_rms_V, fpn = cfg.noise.fixed_pattern_rms_V;
  d.sigma_chip_V = std::sqrt(cmp * cmp + chip.var_V2);
  d.sigma_independent_V =
      std::sqrt(chip.shot_var_V2 + ktc_variance_V2(cfg) + fpn * fpn + d.sigma_chip_V * d.sigma_chip_V);
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
    const Tail t = activation(c.background.mean_V + g.offset_V[i], vcmp, c.background.sigma_independent_V);
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
