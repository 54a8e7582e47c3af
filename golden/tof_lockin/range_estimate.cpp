#include "golden/tof_lockin/range_estimate.h"

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

double fixed_pattern_range_rms_m(double K_m, double mu_a, double mu_b, double fpn_V) {
  const double s = mu_a + mu_b;
  return K_m * std::sqrt(mu_b * mu_b + mu_a * mu_a) / (s * s) * fpn_V;
}

}  // namespace rangesim::golden
