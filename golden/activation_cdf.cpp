#include "golden/activation_cdf.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace rangesim::golden {
namespace {

constexpr double kZCut = 9.0;          // Phi(-9) = 1.13e-19
constexpr double kNegligible = 1e-18;  // early-exit tolerance

// log P(N >= n) Chernoff bound for n > mu, log P(N <= n) bound for n < mu: n - mu - n ln(n / mu).
double log_chernoff(double n, double mu) { return n <= 0 ? -mu : n - mu - n * std::log(n / mu); }

double Phi(double z) { return 0.5 * std::erfc(-z * M_SQRT1_2); }

}  // namespace

ActivationProbability activation_probability(double mu, double t, double s) {
  if (s < 0) s = 0;
  const double cut = kZCut * s;
  if (mu <= 0) {  // no electrons: only the static noise can reach the threshold
    if (s == 0) return t <= 0 ? ActivationProbability{1, 0} : ActivationProbability{0, 1};
    return {Phi(-t / s), Phi(t / s)};
  }
  // Early exits: p <= P(N >= t - cut) + Phi(-9), q <= P(N <= t + cut) + Phi(-9).
  const double n1 = t - cut, n2 = t + cut;
  if (n1 > mu && std::exp(log_chernoff(n1, mu)) + (s > 0 ? 1.2e-19 : 0) < kNegligible) return {0, 1};
  if (n2 < mu && std::exp(log_chernoff(std::max(n2, 0.0), mu)) + (s > 0 ? 1.2e-19 : 0) < kNegligible)
    return {1, 0};

  const double sd = std::sqrt(mu);
  const double nlo = std::max(0.0, std::floor(mu - 13 * sd - 20));
  const double nhi = std::ceil(mu + 13 * sd + 20);
  const double mode = std::min(std::max(std::floor(mu), nlo), nhi);

  // Poisson pmf over the window by recurrence from the mode (started in log space), cut where it
  // falls below 1e-25 of the mode (monotone away from the mode, so the rest is smaller still).
  thread_local std::vector<double> pmf;
  const long lo_i = static_cast<long>(nlo), hi_i = static_cast<long>(nhi), mode_i = static_cast<long>(mode);
  pmf.assign(static_cast<size_t>(hi_i - lo_i + 1), 0.0);
  const double pmf_mode = std::exp(mode * std::log(mu) - mu - std::lgamma(mode + 1));
  long first = mode_i, last = mode_i;
  pmf[mode_i - lo_i] = pmf_mode;
  for (long n = mode_i; n < hi_i; ++n) {
    const double next = pmf[n - lo_i] * mu / (n + 1);
    if (next < 1e-25 * pmf_mode) break;
    pmf[n + 1 - lo_i] = next;
    last = n + 1;
  }
  for (long n = mode_i; n > lo_i; --n) {
    const double prev = pmf[n - lo_i] * n / mu;
    if (prev < 1e-25 * pmf_mode) break;
    pmf[n - 1 - lo_i] = prev;
    first = n - 1;
  }

  double p = 0, q = 0;
  if (s == 0) {
    for (long n = first; n <= last; ++n) (n >= t ? p : q) += pmf[n - lo_i];
  } else {
    // Tails where Phi is 0 or 1 to 1e-19, then the band |z| < 9 where it is evaluated.
    const long band_lo = std::max(first, static_cast<long>(std::floor(t - cut)) + 1);
    const long band_hi = std::min(last, static_cast<long>(std::ceil(t + cut)) - 1);
    for (long n = first; n <= last && n < band_lo; ++n) q += pmf[n - lo_i];
    for (long n = std::max(first, band_hi + 1); n <= last; ++n) p += pmf[n - lo_i];
    if (band_lo <= band_hi) {
      for (long n = band_lo; n <= band_hi; ++n) {
        const double z = (n - t) / s;
        const double small = Phi(-std::fabs(z));  // one erfc per term, for the smaller tail
        p += pmf[n - lo_i] * (z < 0 ? small : 1 - small);
        q += pmf[n - lo_i] * (z < 0 ? 1 - small : small);
      }
    }
  }
  // The window holds all but < 1e-25 of the mass; renormalise away the rounding of the start.
  const double tot = p + q;
  return {p / tot, q / tot};
}

}  // namespace rangesim::golden
