#pragma once
// Significance of a count excess, the common currency of the range maps' validity flags: the
// one-sided p-value of the observed counts under the background-only hypothesis, and the same as
// a Gaussian-equivalent number of standard deviations ("a 5 sigma peak"), so one threshold reads
// the same for every sensor.
namespace rangesim::golden {

// ln P(X >= n) for X ~ Poisson(lambda), lambda > 0, n >= 0 (0 when n <= 0). Exact summation of
// the tail from its first term, so it keeps precision down to P ~ 1e-300.
double poisson_upper_tail_log(long long n, double lambda);

// z with Q(z) = p, Q the standard normal upper tail, from ln p (p in (0, 1]). Negative for
// p > 1/2; capped at 38 (p below ~1e-316).
double sigma_from_log_p(double log_p);

}  // namespace rangesim::golden
