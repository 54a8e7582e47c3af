#include "golden/common/activation_cdf.h"

#include <algorithm>
#include <cmath>

namespace rangesim::golden {
namespace {

constexpr double kZCut = 9.0;          // Phi(-9) = 1.13e-19
constexpr double kNegligible = 1e-18;  // early-exit tolerance

// log P(N >= n) Chernoff bound for n > mu, log P(N <= n) bound for n < mu: n - mu - n ln(n / mu).
double log_chernoff(double n, double mu) { return n <= 0 ? -mu : n - mu - n * std::log(n / mu); }

double Phi(double z) { return 0.5 * std::erfc(-z * M_SQRT1_2); }

// P(n + R >= t) and its complement for one electron count n inside the band |n - t| < 9 s: the
// smaller tail from one erfc, the larger as its complement.
ActivationProbability band_split(double n, double t, double s) {
  const double z = (n - t) / s;
  const double small = Phi(-std::fabs(z));
  return z < 0 ? ActivationProbability{small, 1 - small} : ActivationProbability{1 - small, small};
}

// The sum of activation_probability with the band's split given by `split(n)` (computed, or looked
// up in a table of the same values): both give the same bits.
template <class Split>
ActivationProbability activation_sum(double mu, double t, double s, const Split& split) {
  if (s < 0) s = 0;
  // A threshold beyond any electron count (e.g. theta / A_sf overflowing for a tiny gain) is
  // never or always reached; keep the arithmetic below finite.
  if (t == INFINITY) return {0, 1};
  if (t == -INFINITY) return {1, 0};
  const double cut = kZCut * s;
  if (mu <= 0) {  // no electrons: only the static noise can reach the threshold
    if (s == 0) return t <= 0 ? ActivationProbability{1, 0} : ActivationProbability{0, 1};
    return {Phi(-t / s), Phi(t / s)};
  }
  // Early exits: p <= P(N >= t - cut) + Phi(-9), q <= P(N <= t + cut) + Phi(-9).
  const double n1 = t - cut, n2 = t + cut;
  if (n1 > mu && std::exp(log_chernoff(n1, mu)) + (s > 0 ? 1.2e-19 : 0) < kNegligible) return {0, 1};
  if (n2 < mu && std::exp(log_chernoff(std::max(n2, 0.0), mu)) + (s > 0 ? 1.2e-19 : 0) < kNegligible) return {1, 0};

  const double sd = std::sqrt(mu);
  const double nlo = std::max(0.0, std::floor(mu - 13 * sd - 20));
  const double nhi = std::ceil(mu + 13 * sd + 20);
  const double mode = std::min(std::max(std::floor(mu), nlo), nhi);

  // Poisson pmf by recurrence outwards from the mode (started in log space), summed on the fly
  // (no storage: the window is ~26 sqrt(mu) wide), cut where it falls below 1e-25 of the mode
  // (monotone away from the mode, so the rest is smaller still). Each term goes to p or q by
  // its noise-free side of the threshold, or is split by Phi inside the band |z| < 9.
  double p = 0, q = 0;
  auto add = [&](double n, double w) {
    if (s == 0) {
      (n >= t ? p : q) += w;
      return;
    }
    if (n <= t - cut) {
      q += w;
    } else if (n >= t + cut) {
      p += w;
    } else {
      const ActivationProbability b = split(n);
      p += w * b.p;
      q += w * b.q;
    }
  };
  const double pmf_mode = std::exp(mode * std::log(mu) - mu - std::lgamma(mode + 1));
  add(mode, pmf_mode);
  for (double n = mode, cur = pmf_mode; n < nhi; ++n) {
    cur *= mu / (n + 1);
    if (cur < 1e-25 * pmf_mode) break;
    add(n + 1, cur);
  }
  for (double n = mode, cur = pmf_mode; n > nlo; --n) {
    cur *= n / mu;
    if (cur < 1e-25 * pmf_mode) break;
    add(n - 1, cur);
  }
  // The window holds all but < 1e-25 of the mass; renormalise away the rounding of the start.
  const double tot = p + q;
  return {p / tot, q / tot};
}

}  // namespace

ActivationProbability activation_probability(double mu, double t, double s) {
  return activation_sum(mu, t, s, [&](double n) { return band_split(n, t, s); });
}

ActivationTable::ActivationTable(double threshold_e, double sigma_e) : t_(threshold_e), s_(std::max(sigma_e, 0.0)) {
  if (!(s_ > 0) || !std::isfinite(t_)) return;
  // Every integer n with t - cut < n < t + cut: the band of activation_sum.
  const double cut = kZCut * s_;
  first_ = std::floor(t_ - cut) + 1;
  for (double n = first_; n < t_ + cut; ++n) split_.push_back(band_split(n, t_, s_));
}

ActivationProbability ActivationTable::operator()(double mean_e) const {
  if (split_.empty()) return activation_probability(mean_e, t_, s_);
  return activation_sum(mean_e, t_, s_, [&](double n) {
    const double i = n - first_;
    // n is inside the band here; the guard only keeps rounding of t +- cut from reading past it.
    if (i < 0 || i >= static_cast<double>(split_.size())) return band_split(n, t_, s_);
    return split_[static_cast<std::size_t>(i)];
  });
}

}  // namespace rangesim::golden
