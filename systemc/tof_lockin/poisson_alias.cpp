#include "systemc/tof_lockin/poisson_alias.h"

#include <cmath>
#include <stdexcept>

#include "systemc/common/poisson_sampler.h"

namespace rangesim::systemc::lockin {

namespace {

constexpr long double kTailMass = 1.0L / 73786976294838206464.0L;  // 2^-66 on each side
constexpr long double kTwo64 = 18446744073709551616.0L;

}  // namespace

PoissonAlias::PoissonAlias(double mean) : mean_(mean) {
  if (!(mean >= 0.0) || mean > kMaxMean) throw std::logic_error("PoissonAlias: mean outside 0 .. 1e8");
  if (mean == 0.0) {
    threshold_.assign(1, ~0ULL), alias_.assign(1, 0);
    return;
  }
  const long double mu = mean;
  // The mode's probability from the accurate log pmf, then outwards by the exact ratios.
  const long long mode = static_cast<long long>(std::floor(mean));
  const long double p_mode =
      std::exp(static_cast<long double>(PoissonSampler::log_pmf(mean, static_cast<double>(mode))));
  std::vector<long double> up{p_mode}, down;  // up: mode, mode+1, ...; down: mode-1, mode-2, ...
  long double tail_hi = 0, tail_lo = 0;
  for (long long k = mode;; ++k) {  // mass above k <= p(k+1) / (1 - mu / (k + 2))
    const long double next = up.back() * mu / static_cast<long double>(k + 1);
    tail_hi = next / (1 - mu / static_cast<long double>(k + 2));
    if (tail_hi < kTailMass) break;
    up.push_back(next);
  }
  for (long long k = mode; k > 0;) {  // mass below k <= p(k-1) / (1 - (k-1) / mu)
    const long double prev = (down.empty() ? p_mode : down.back()) * static_cast<long double>(k) / mu;
    tail_lo = prev / (1 - static_cast<long double>(k - 1) / mu);
    if (tail_lo < kTailMass) break;
    down.push_back(prev);
    --k;
    if (k == 0) tail_lo = 0;
  }
  first_ = mode - static_cast<long long>(down.size());
  std::vector<long double> p(down.rbegin(), down.rend());
  p.insert(p.end(), up.begin(), up.end());
  left_out_ = static_cast<double>(tail_hi + tail_lo);
  size_ = static_cast<std::uint32_t>(p.size());
  long double sum = 0;
  for (long double x : p) sum += x;

  // Vose: buckets scaled to mean 1; each small bucket is topped up by a large one.
  const long double n = static_cast<long double>(size_);
  std::vector<long double> q(size_);
  std::vector<std::uint32_t> small, large;
  for (std::uint32_t i = 0; i < size_; ++i) {
    q[i] = p[i] / sum * n;
    (q[i] < 1 ? small : large).push_back(i);
  }
  threshold_.assign(size_, ~0ULL);
  alias_.resize(size_);
  for (std::uint32_t i = 0; i < size_; ++i) alias_[i] = i;
  while (!small.empty() && !large.empty()) {
    const std::uint32_t s = small.back(), l = large.back();
    small.pop_back();
    threshold_[s] = static_cast<std::uint64_t>(q[s] * kTwo64);
    alias_[s] = l;
    q[l] -= 1 - q[s];
    if (q[l] < 1) large.pop_back(), small.push_back(l);
  }
  // What is left is full to rounding: keep the bucket always (threshold ~0, alias itself).
}

std::vector<long double> PoissonAlias::probabilities() const {
  std::vector<long double> p(size_, 0);
  for (std::uint32_t i = 0; i < size_; ++i) {
    const long double keep = threshold_[i] == ~0ULL ? 1 : static_cast<long double>(threshold_[i]) / kTwo64;
    p[i] += keep;
    if (alias_[i] != i) p[alias_[i]] += 1 - keep;
  }
  for (long double& x : p) x /= static_cast<long double>(size_);
  return p;
}

}  // namespace rangesim::systemc::lockin
