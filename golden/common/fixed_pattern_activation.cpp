#include "golden/common/fixed_pattern_activation.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "golden/common/pixel.h"
#include "golden/common/position_noise.h"

namespace rangesim::golden {

namespace {

constexpr double kReach = 8.5;  // nodes over z in [-8.5, 8.5]

// 8-point Gauss-Legendre on [-1, 1].
constexpr double kGlX[4] = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267, 0.9602898564975363};
constexpr double kGlW[4] = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763};

struct Rule {
  std::vector<double> z, w;  // nodes and weights (summing to 1)
};

// Adds [a, b] in panels of width <= h, the standard normal density in the weights.
void add_panels(double a, double b, double h, Rule& r) {
  if (!(b > a)) return;
  const int n = static_cast<int>(std::ceil((b - a) / h));
  const double step = (b - a) / n;
  for (int i = 0; i < n; ++i) {
    const double mid = a + (i + 0.5) * step, half = 0.5 * step;
    for (int j = 0; j < 4; ++j)
      for (double sgn : {-1.0, 1.0}) {
        const double z = mid + sgn * half * kGlX[j];
        r.z.push_back(z);
        r.w.push_back(half * kGlW[j] * std::exp(-0.5 * z * z));
      }
  }
}

// The rule for a term of slope `slope_e` electrons per unit z on an activation step
// sqrt(lambda + sigma^2) electrons wide, with a kink (the clip at zero) at `kink_z`: panels of at
// most 0.5 and a third of the step's width in z, split at the kink.
Rule rule_for(double slope_e, double lambda_e, double sigma_e, double kink_z, double scale) {
  if (!(slope_e > 0)) return {{0.0}, {1.0}};
  const double width_z = std::sqrt(std::max(lambda_e, 0.0) + sigma_e * sigma_e + 1.0) / slope_e;
  const double h = std::min(0.5, width_z / 3) / scale;
  Rule r;
  const double k = std::clamp(kink_z, -kReach, kReach);
  add_panels(-kReach, k, h, r);
  add_panels(k, kReach, h, r);
  double sum = 0;
  for (double w : r.w) sum += w;
  for (double& w : r.w) w /= sum;
  return r;
}

}  // namespace

double static_noise_V(const LsConventionalConfig& cfg) {
  return std::hypot(static_noise_V(cfg.pixel),
                    cfg.fixed_pattern.comparator_offset_rms_V / cfg.pixel.source_follower_gain);
}

bool fixed_pattern_spreads_mean(const LsConventionalConfig& cfg) {
  return cfg.fixed_pattern.prnu_fraction > 0 || cfg.fixed_pattern.dsnu_rms > 0;
}

ActivationProbability fixed_pattern_activation(const LsConventionalConfig& cfg, ActivationCache& cache, double photo_e,
                                               double t_over_T, double threshold_e, double sigma_e, double scale) {
  const double p = cfg.fixed_pattern.prnu_fraction, d = cfg.fixed_pattern.dsnu_rms;
  const PixelConfig& px = cfg.pixel;
  // Electrons per ampere of dark current by this sampling: t / C in electrons.
  const double per_A = px.integration_time_s / px.pd_capacitance_F * electrons_per_volt(px) * t_over_T;
  const double dark_e = dark_voltage_V(px) * electrons_per_volt(px) * t_over_T;
  const double lambda = photo_e + dark_e;
  // Kinks: the gain clips at z = -1 / p, the dark current at z' = -I_d / d.
  const Rule g = rule_for(p * photo_e, lambda, sigma_e, p > 0 ? -1 / p : -kReach, scale);
  const Rule k = rule_for(d * per_A, lambda, sigma_e, d > 0 ? -px.dark_current_A / d : -kReach, scale);
  ActivationProbability out{0, 0};
  for (std::size_t i = 0; i < g.z.size(); ++i) {
    const double photo = std::max(0.0, 1 + p * g.z[i]) * photo_e;
    for (std::size_t j = 0; j < k.z.size(); ++j) {
      const double dark = d > 0 ? std::max(0.0, px.dark_current_A + d * k.z[j]) * per_A : dark_e;
      const ActivationProbability a = cache.get(photo + dark, threshold_e, sigma_e);
      out.p += g.w[i] * k.w[j] * a.p;
      out.q += g.w[i] * k.w[j] * a.q;
    }
  }
  return out;
}

}  // namespace rangesim::golden
