#include "golden/tof_lockin/range_estimate.h"

#include <algorithm>
#include <cmath>

namespace rangesim::golden {

RangeMoments range_moments(double K_m, double mu_a, double var_a, double mu_b, double var_b) {
  const double s = mu_a + mu_b;
  const double s2 = s * s, s3 = s2 * s, s4 = s2 * s2;
  const double fa = -mu_b / s2, fb = mu_a / s2;
  const double faa = 2.0 * mu_b / s3, fbb = -2.0 * mu_a / s3, fab = (mu_b - mu_a) / s3;
  const double faaa = -6.0 * mu_b / s4, fbbb = 6.0 * mu_a / s4;
  const double faab = (2.0 * mu_a - 4.0 * mu_b) / s4, fabb = (4.0 * mu_a - 2.0 * mu_b) / s4;

  RangeMoments r;
  r.noise_free_m = K_m * mu_b / s;
  r.mean_m = K_m * (mu_b / s + (mu_b * var_a - mu_a * var_b) / s3);
  const double var1 = fa * fa * var_a + fb * fb * var_b;
  // sum over (i, j) in {a, b}^2 of (f_ij^2 / 2 + f_i f_ijj) v_i v_j.
  const double var2 = (0.5 * faa * faa + fa * faaa) * var_a * var_a + (0.5 * fbb * fbb + fb * fbbb) * var_b * var_b +
                      (0.5 * fab * fab + fa * fabb) * var_a * var_b + (0.5 * fab * fab + fb * faab) * var_a * var_b;
  r.var_first_m2 = K_m * K_m * var1;
  // The expansion is asymptotic; where the correction would make the variance negative the
  // SNR is far too low for it and the first-order value is kept.
  r.var_m2 = K_m * K_m * (var1 + var2 > 0.0 ? var1 + var2 : var1);
  r.snr = s / std::sqrt(var_a + var_b);
  return r;
}

ConditionalRangeMoments range_moments_given_range(double K_m, double mu_a, double var_a, double mu_b, double var_b,
                                                  double s_min) {
  ConditionalRangeMoments r;
  static_cast<RangeMoments&>(r) = range_moments(K_m, mu_a, var_a, mu_b, var_b);
  const double mu_s = mu_a + mu_b, v_s = var_a + var_b, sd_s = std::sqrt(v_s);
  const double beta = var_b / v_s, c = var_a * var_b / v_s;  // b | s ~ N(mu_b + beta (s - mu_s), c)
  // z = (s - mu_s) / sd_s from the threshold to 12 (the density below 1e-31 beyond) in panels of
  // 1/8 sigma with 8-point Gauss-Legendre: E[f(s) 1{s >= s_min}] for f = 1, m / s, (m^2 + c) / s^2.
  static const double x[4] = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267, 0.9602898564975363};
  static const double w[4] = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763};
  const double z_lo = std::max((s_min - mu_s) / sd_s, -40.0), z_hi = 12.0;
  double p = 0, e1 = 0, e2 = 0;
  if (z_lo < z_hi) {
    const int panels = static_cast<int>(std::ceil((z_hi - z_lo) * 8.0));
    const double h = (z_hi - z_lo) / panels;
    for (int i = 0; i < panels; ++i) {
      const double mid = z_lo + (i + 0.5) * h;
      for (int j = 0; j < 8; ++j) {
        const double z = mid + (j < 4 ? -x[j] : x[j - 4]) * h / 2, wt = w[j % 4] * h / 2;
        const double dens = wt * std::exp(-0.5 * z * z) * 0.3989422804014327;  // 1 / sqrt(2 pi)
        const double sv = mu_s + sd_s * z, m = mu_b + beta * (sv - mu_s);
        p += dens;
        e1 += dens * m / sv;
        e2 += dens * (m * m + c) / (sv * sv);
      }
    }
  }
  r.p_range = p;
  if (p > 0) {
    const double mean = e1 / p;
    r.mean_m = K_m * mean;
    r.var_m2 = K_m * K_m * std::max(0.0, e2 / p - mean * mean);
  }
  return r;
}

double fixed_pattern_range_rms_m(double K_m, double mu_a, double mu_b, double fpn_V) {
  const double s = mu_a + mu_b;
  return K_m * std::sqrt(mu_b * mu_b + mu_a * mu_a) / (s * s) * fpn_V;
}

}  // namespace rangesim::golden
