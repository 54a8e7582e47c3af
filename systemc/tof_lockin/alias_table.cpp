#include "systemc/tof_lockin/alias_table.h"

#include <cmath>
#include <stdexcept>

#include "systemc/common/poisson_sampler.h"

namespace rangesim::systemc::lockin {

namespace {

constexpr double kTailMass = 1.0 / 73786976294838206464.0;  // 2^-66 on each side
constexpr long double kTwo64 = 18446744073709551616.0L;

}  // namespace

double PoissonAlias::checked(double mean) {
  if (!(mean >= 0.0) || mean > kMaxMean) throw std::logic_error("PoissonAlias: mean outside 0 .. 1e8");
  return mean;
}

PoissonWindow poisson_window(double mean) {
  PoissonWindow w;
  if (mean == 0.0) {
    w.p.assign(1, 1.0);
    return w;
  }
  // The mode's probability from the accurate log pmf, then outwards by the exact ratios. The
  // window is filled from the middle of a buffer wide enough for both tails (+-9.6 sigma + slack).
  const double mu = mean;
  const long long mode = static_cast<long long>(std::floor(mean));
  const std::size_t half = static_cast<std::size_t>(12.0 * std::sqrt(mu) + 64.0);
  std::vector<double> p(2 * half + 1);
  std::size_t lo = half, hi = half;  // p[lo .. hi] holds counts mode - (half - lo) .. mode + (hi - half)
  p[half] = std::exp(PoissonSampler::log_pmf(mean, static_cast<double>(mode)));
  double tail_hi = 0, tail_lo = 0;
  const auto anchored = [&](double ratio_step, long long k, long long steps) {
    return steps % 128 == 0 ? std::exp(PoissonSampler::log_pmf(mean, static_cast<double>(k))) : ratio_step;
  };
  for (long long k = mode;; ++k) {  // mass above k <= p(k+1) / (1 - mu / (k + 2))
    const double next = anchored(p[hi] * mu / static_cast<double>(k + 1), k + 1, k + 1 - mode);
    // The bound needs a division: only out where the tail can be that small.
    tail_hi = next < 1e-17 ? next / (1 - mu / static_cast<double>(k + 2)) : 1.0;
    if (tail_hi < kTailMass || hi + 1 == p.size()) break;
    p[++hi] = next;
  }
  for (long long k = mode; k > 0 && lo > 0; --k) {  // mass below k <= p(k-1) / (1 - (k-1) / mu)
    const double prev = anchored(p[lo] * static_cast<double>(k) / mu, k - 1, mode - k + 1);
    tail_lo = prev < 1e-17 ? prev / (1 - static_cast<double>(k - 1) / mu) : 1.0;
    if (tail_lo < kTailMass) break;
    p[--lo] = prev;
    if (k == 1) tail_lo = 0;
  }
  w.first = mode - static_cast<long long>(half - lo);
  w.mass_left_out = tail_hi + tail_lo;
  w.p.assign(p.begin() + static_cast<std::ptrdiff_t>(lo), p.begin() + static_cast<std::ptrdiff_t>(hi) + 1);
  return w;
}

AliasTable::AliasTable(const std::vector<double>& pmf, long long first)
    : first_(first), size_(static_cast<std::uint32_t>(pmf.size())) {
  long double sum = 0;  // 64-bit mantissa: the running sum below stays within a unit
  for (double x : pmf) sum += x;
  // Vose in integers, so nothing drifts: each bucket's share is a count of units 2^-shift of one
  // bucket, and topping up a small bucket from a large one is exact. The counts are differences
  // of the rounded cumulative sums, so they add up to exactly size x 2^shift and each is within a
  // unit of its share. shift is as large as 63 bits allow: one unit is below 2^-62 of the total.
  int bits = 0;
  while ((std::uint64_t{1} << bits) < size_) ++bits;
  const int shift = 63 - bits;
  const std::uint64_t unit_sum = std::uint64_t{1} << shift;  // one full bucket
  const long double scale = static_cast<long double>(size_) * static_cast<long double>(unit_sum) / sum;
  std::vector<std::uint64_t> q(size_);
  long double running = 0;
  std::uint64_t before = 0;
  for (std::uint32_t i = 0; i < size_; ++i) {
    running += pmf[i];
    const std::uint64_t upto = i + 1 == size_ ? static_cast<std::uint64_t>(size_) * unit_sum
                                              : static_cast<std::uint64_t>(running * scale + 0.5L);
    q[i] = upto - before;
    before = upto;
  }
  std::vector<std::uint32_t> small, large;
  small.reserve(size_), large.reserve(size_);
  for (std::uint32_t i = 0; i < size_; ++i) (q[i] < unit_sum ? small : large).push_back(i);
  threshold_.assign(size_, ~0ULL);
  alias_.resize(size_);
  for (std::uint32_t i = 0; i < size_; ++i) alias_[i] = i;
  while (!small.empty() && !large.empty()) {
    const std::uint32_t sm = small.back(), l = large.back();
    small.pop_back();
    threshold_[sm] = q[sm] << (64 - shift);  // the share of bucket sm kept, in 2^-64
    alias_[sm] = l;
    q[l] -= unit_sum - q[sm];
    if (q[l] < unit_sum) large.pop_back(), small.push_back(l);
  }
  // Exact arithmetic leaves only full buckets: kept always (threshold ~0, alias itself).
}

std::vector<long double> AliasTable::probabilities() const {
  std::vector<long double> p(size_, 0);
  for (std::uint32_t i = 0; i < size_; ++i) {
    const long double keep = threshold_[i] == ~0ULL ? 1 : static_cast<long double>(threshold_[i]) / kTwo64;  // exact
    p[i] += keep;
    if (alias_[i] != i) p[alias_[i]] += 1 - keep;
  }
  for (long double& x : p) x /= static_cast<long double>(size_);
  return p;
}

}  // namespace rangesim::systemc::lockin
