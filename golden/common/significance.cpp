#include "golden/common/significance.h"

#include <algorithm>
#include <cmath>

namespace rangesim::golden {

double poisson_upper_tail_log(long long n, double lambda) {
  if (n <= 0) return 0.0;
  const double k0 = static_cast<double>(n);
  // Past the mode the terms fall at least as fast as lambda / (k + 1): sum them from the first.
  // Below it the tail holds most of the mass; its complement is summed instead.
  if (k0 > lambda) {
    const double log_first = -lambda + k0 * std::log(lambda) - std::lgamma(k0 + 1);
    double sum = 1, term = 1;
    for (double k = k0 + 1; term > 1e-17 * sum && k < k0 + 1e7; ++k) sum += (term *= lambda / k);
    return log_first + std::log(sum);
  }
  if (lambda > 700)  // e^-lambda underflows; n <= lambda here, so P >= ~1/2: the normal limit
    return std::log(0.5 * std::erfc((k0 - 0.5 - lambda) / std::sqrt(lambda) * M_SQRT1_2));
  double below = 0, term = std::exp(-lambda);  // P(X < n), n <= lambda
  for (long long k = 0; k < n; ++k) below += term, term *= lambda / static_cast<double>(k + 1);
  return std::log1p(-std::min(below, 1.0));
}

double sigma_from_log_p(double log_p) {
  log_p = std::min(log_p, 0.0);
  const auto log_q = [](double z) { return std::log(0.5 * std::erfc(z * M_SQRT1_2)); };
  double lo = -38, hi = 38;
  if (log_p <= log_q(hi)) return hi;
  for (int i = 0; i < 80; ++i) {  // Q is decreasing: bisect to double precision
    const double mid = 0.5 * (lo + hi);
    (log_q(mid) > log_p ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace rangesim::golden
