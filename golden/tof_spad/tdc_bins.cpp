#include "golden/tof_spad/tdc_bins.h"

#include <algorithm>
#include <cmath>

namespace rangesim::golden::spad {

namespace {

unsigned long long splitmix64(unsigned long long x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

double unit_open(unsigned long long bits) { return (static_cast<double>(bits >> 11) + 0.5) * 0x1.0p-53; }

}  // namespace

double keyed_normal(unsigned long long seed, unsigned long long index) {
  const unsigned long long k = splitmix64(seed ^ splitmix64(index));
  const double u1 = unit_open(splitmix64(k)), u2 = unit_open(splitmix64(k + 1));
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * M_PI * u2);
}

TdcBins make_tdc_bins(const TdcConfig& tdc, double period_s) {
  TdcBins b;
  b.lsb_s = tdc.lsb_s;
  b.period_s = period_s;
  // A period that is a whole number of LSB (to 1e-9) has no partial last step.
  b.phase_bins = std::max(1, static_cast<int>(std::ceil(period_s / tdc.lsb_s - 1e-9)));
  const double range_codes = std::floor(tdc.full_range_s / tdc.lsb_s + 1e-9);
  b.codes = static_cast<int>(std::min({static_cast<double>(b.phase_bins), range_codes, std::ldexp(1.0, tdc.bits)}));
  b.codes = std::max(b.codes, 1);

  const int np = b.phase_bins, nc = b.codes;
  b.edges_s.assign(static_cast<size_t>(np) + 1, 0.0);
  const double bow_amplitude = std::sqrt(2.0) * tdc.inl_rms_lsb;  // rms of a sine = amplitude / sqrt(2)
  const double edge_jitter = tdc.dnl_rms_lsb / std::sqrt(2.0);
  const auto seed = static_cast<unsigned long long>(tdc.nonlinearity_seed);
  for (int i = 1; i < np; ++i) {
    double inl = 0;
    if (i < nc) inl = bow_amplitude * std::sin(2.0 * M_PI * i / nc) + edge_jitter * keyed_normal(seed, i);
    b.edges_s[static_cast<size_t>(i)] = tdc.lsb_s * (i + inl);
  }
  b.edges_s[static_cast<size_t>(np)] = period_s;
  // Keep every bin at least 5% of an LSB wide: a TDC code never swallows its neighbour.
  for (int i = 1; i <= np; ++i) {
    auto& e = b.edges_s[static_cast<size_t>(i)];
    e = std::max(e, b.edges_s[static_cast<size_t>(i) - 1] + 0.05 * std::min(tdc.lsb_s, period_s / np));
  }
  for (int i = np - 1; i >= 1; --i) {  // and below the period end
    auto& e = b.edges_s[static_cast<size_t>(i)];
    e = std::min(e, b.edges_s[static_cast<size_t>(i) + 1] - 0.05 * std::min(tdc.lsb_s, period_s / np));
  }
  return b;
}

}  // namespace rangesim::golden::spad
