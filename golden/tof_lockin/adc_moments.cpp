#include "golden/tof_lockin/adc_moments.h"

#include <algorithm>
#include <cmath>

namespace rangesim::golden {

QuantisedMoments quantised_moments(double mean_V, double sigma_V, double lsb_V, long long codes) {
  const double top = static_cast<double>(codes - 1);
  QuantisedMoments m;
  if (!(sigma_V > 0.0)) {  // deterministic input
    const double code = std::clamp(std::floor(mean_V / lsb_V), 0.0, top);
    m.mean_V = code * lsb_V;
    return m;
  }
  const double lo_V = mean_V - 9.0 * sigma_V, hi_V = mean_V + 9.0 * sigma_V;
  if (sigma_V >= 1.5 * lsb_V && lo_V > lsb_V && hi_V < top * lsb_V) {
    m.mean_V = mean_V - lsb_V / 2.0;
    m.var_V2 = sigma_V * sigma_V + lsb_V * lsb_V / 12.0;
    return m;
  }
  // Direct sums over the codes k whose threshold k Delta lies within mu +- 9 sigma; below that
  // window P(V >= k Delta) = 1 (counted in closed form), above it 0.
  const double k_first = std::max(1.0, std::ceil(lo_V / lsb_V));
  const double k_last = std::min(top, std::floor(hi_V / lsb_V));
  // Codes 1 .. k_first - 1 are certainly reached: sum 1 and sum (2k - 1) = (k_first - 1)^2.
  const double n_sure = std::clamp(k_first - 1.0, 0.0, top);
  double e1 = n_sure, e2 = n_sure * n_sure;
  for (double k = k_first; k <= k_last; k += 1.0) {
    const double p = 0.5 * std::erfc((k * lsb_V - mean_V) / (sigma_V * std::sqrt(2.0)));
    e1 += p;
    e2 += (2.0 * k - 1.0) * p;
  }
  m.mean_V = e1 * lsb_V;
  m.var_V2 = std::max(0.0, e2 - e1 * e1) * lsb_V * lsb_V;
  return m;
}

}  // namespace rangesim::golden
