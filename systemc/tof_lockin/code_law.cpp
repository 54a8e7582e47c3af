#include "systemc/tof_lockin/code_law.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace rangesim::systemc::lockin {

AliasTable tap_code_table(const TapFrameLaw& law, const LockinPixelKernel::Readout& r, const ColumnAdcKernel& adc,
                          int tap) {
  if (law.may_saturate || !(law.sigma_V > 0))
    throw std::logic_error("tap_code_table: needs a law without the V_sat clip");
  const PoissonWindow w = poisson_window(law.count_mean_e);
  const double g = r.volts_per_e[tap], base = r.a_sf * r.offset_V, sigma = law.sigma_V, lsb = adc.lsb_V();
  const auto mu = [&](std::size_t i) {
    return g * (static_cast<double>(w.first + static_cast<long long>(i)) - law.offset_e) + base;
  };
  const std::size_t n = w.p.size();
  // Prefix sums of p (long double): P(N < first + i).
  std::vector<long double> below(n + 1, 0);
  for (std::size_t i = 0; i < n; ++i) below[i + 1] = below[i] + w.p[i];
  const long double total = below[n];
  const double reach = 9.0 * sigma;
  const long long top = adc.top_code();
  const long long c_lo = std::clamp(static_cast<long long>(std::floor((mu(0) - reach) / lsb)), 0LL, top);
  const long long c_hi = std::clamp(static_cast<long long>(std::floor((mu(n - 1) + reach) / lsb)), 0LL, top);
  // F(c) = P(v < c LSB) for the boundaries c_lo + 1 .. c_hi.
  std::vector<long double> F;
  F.reserve(static_cast<std::size_t>(c_hi - c_lo));
  for (long long c = c_lo + 1; c <= c_hi; ++c) {
    const double b = static_cast<double>(c) * lsb;
    // Counts whose mean is more than 9 sigma below b are below it for sure; above, never.
    const auto i_lo = static_cast<std::size_t>(std::clamp<double>(
        std::ceil((b - reach - base) / g + law.offset_e) - static_cast<double>(w.first), 0.0, static_cast<double>(n)));
    const auto i_hi = static_cast<std::size_t>(
        std::clamp<double>(std::floor((b + reach - base) / g + law.offset_e) - static_cast<double>(w.first) + 1, 0.0,
                           static_cast<double>(n)));
    long double f = below[std::min(i_lo, n)];
    for (std::size_t i = i_lo; i < i_hi; ++i)
      f += static_cast<long double>(w.p[i]) * (0.5 * std::erfc((mu(i) - b) / (sigma * std::sqrt(2.0))));
    F.push_back(f / total);
  }
  std::vector<double> pmf(static_cast<std::size_t>(c_hi - c_lo + 1));
  for (std::size_t k = 0; k < pmf.size(); ++k) {
    const long double upper = k < F.size() ? F[k] : 1.0L, lower = k == 0 ? 0.0L : F[k - 1];
    pmf[k] = static_cast<double>(std::max(0.0L, upper - lower));
  }
  return AliasTable(pmf, c_lo);
}

}  // namespace rangesim::systemc::lockin
