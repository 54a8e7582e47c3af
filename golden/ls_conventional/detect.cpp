#include "golden/ls_conventional/detect.h"

#include <cmath>

#include "golden/common/activation_cdf.h"
#include "golden/common/fixed_pattern_activation.h"
#include "golden/common/pixel.h"
#include "golden/common/position_noise.h"
#include "golden/common/quantiser.h"
#include "golden/common/threshold.h"

namespace rangesim::golden {

double pixel_false_activation_probability(const LsConventionalConfig& cfg, double background_V) {
  const double e_per_V = electrons_per_volt(cfg.pixel);
  const double mean_e = (background_V + dark_voltage_V(cfg.pixel)) * e_per_V;
  const double thr_e = comparator_threshold_V(cfg, background_V) / cfg.pixel.source_follower_gain * e_per_V;
  // Activation is nested in time, so "ever during the frame" = "by the last sampling". The chip's
  // comparator offsets widen the static noise; its PRNU / DSNU spread the mean (fixed_pattern_activation.h).
  const double sig_e = static_noise_V(cfg) * e_per_V;
  if (!fixed_pattern_spreads_mean(cfg)) return activation_probability(mean_e, thr_e, sig_e).p;
  ActivationCache cache;
  return fixed_pattern_activation(cfg, cache, background_V * e_per_V, 1.0, thr_e, sig_e).p;
}

double row_false_activation_probability(const LsConventionalConfig& cfg, double background_V) {
  const double p = pixel_false_activation_probability(cfg, background_V);
  return -std::expm1(cfg.pixel.columns * std::log1p(-p));
}

Detect classify(const LsConventionalConfig& cfg, double signal_V, double background_V) {
  const double dark = dark_voltage_V(cfg.pixel);
  const double A = cfg.pixel.source_follower_gain;
  const double theta = comparator_threshold_V(cfg, background_V);
  if (saturates(cfg.pixel, signal_V + background_V + dark)) return Detect::Saturated;
  // Up to rounding (golden/common/threshold.h): the thesis point 0.01 V / 0.001 V sits exactly on theta.
  if (below_threshold(A * (signal_V + background_V + dark), theta)) return Detect::BelowThreshold;
  if (reaches_threshold(A * (background_V + dark), theta)) return Detect::BackgroundActivation;
  if (row_false_activation_probability(cfg, background_V) > cfg.comparator.false_activation_max)
    return Detect::BackgroundActivation;
  return Detect::Detectable;
}

}  // namespace rangesim::golden
