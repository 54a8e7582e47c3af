#pragma once
// Exact Poisson and normal samplers for the pixel kernels, written for speed and for bits that do
// not depend on the standard library (std::poisson_distribution differs between libraries and
// its setup calls lgamma per mean).
//
// PoissonSampler draws Poisson(mu) for a fixed mu from a pcg32 stream:
//   mu < 10: inversion by sequential search from 0 (one uniform, about mu + 1 steps);
//   mu >= 10: the transformed rejection with squeeze "PTRS" (W. Hormann, "The transformed
//   rejection method for generating Poisson random variables", Insurance: Mathematics and
//   Economics 12, 1993): a hat from a transformed uniform, two uniforms per trial, about 1.15
//   trials; most are accepted by the squeeze without a log or lgamma.
// Both are exact in distribution (up to double rounding); tests/skipping/test_poisson_sampler.cpp
// checks moments and KS against the pmf, and that the test sees a 3 % change of mu.
#include <cmath>

#include "systemc/common/random_stream.h"

namespace rangesim::systemc {

class PoissonSampler {
 public:
  PoissonSampler() = default;
  explicit PoissonSampler(double mean_) : mu_(mean_) {
    if (mu_ < kInversionBelow) {
      exp_neg_mu_ = std::exp(-mu_);
    } else {
      const double smu = std::sqrt(mu_);
      b_ = 0.931 + 2.53 * smu;
      a_ = -0.059 + 0.02483 * b_;
      inv_alpha_ = 1.1239 + 1.1328 / (b_ - 3.4);
      v_r_ = 0.9277 - 3.6224 / (b_ - 2);
    }
  }

  double mean() const { return mu_; }

  // Any stream with a uniform_open01(rng) overload (pcg32 here; the tof-lockin counter-based stream).
  template <class Rng>
  long long operator()(Rng& rng) const {
    if (mu_ <= 0) return 0;
    if (mu_ < kInversionBelow) {
      const double u = uniform_open01(rng);
      long long k = 0;
      double p = exp_neg_mu_, cdf = p;
      while (u > cdf && p > 0) {  // p underflows only where cdf == 1 in doubles
        ++k;
        p *= mu_ / static_cast<double>(k);
        cdf += p;
      }
      return k;
    }
    for (;;) {
      const double u = uniform_open01(rng) - 0.5, v = uniform_open01(rng);
      const double us = 0.5 - std::abs(u);
      const double k = std::floor((2 * a_ / us + b_) * u + mu_ + 0.43);
      if (us >= 0.07 && v <= v_r_) return static_cast<long long>(k);  // squeeze: inside the pmf
      if (k < 0 || (us < 0.013 && v > us)) continue;
      // Outside the squeeze: accept iff the point lies under log p(k).
      if (std::log(v * inv_alpha_ / (a_ / (us * us) + b_)) <= log_pmf(mu_, k)) return static_cast<long long>(k);
    }
  }

  // log p(k) = -mu + k ln mu - ln k!. Summed directly its three terms of size mu ln mu cancel to
  // O(ln mu): at mu = 1e12 only ~1e-2 of the result is left in doubles. For k >= 16, ln k! is
  // taken as Stirling's k ln k - k + ln(2 pi k)/2 plus its remainder series (error < 2e-14), so
  // with d = mu - k the result is k ln(1 + d/k) - d - ln(2 pi k)/2 - r(k): terms of size d, not mu.
  static double log_pmf(double mu, double k) {
    if (k < 16) return -mu + k * std::log(mu) - std::lgamma(k + 1);
    const double d = mu - k, ik = 1 / k, ik2 = ik * ik;
    const double r = ik * (1.0 / 12 - ik2 * (1.0 / 360 - ik2 * (1.0 / 1260 - ik2 / 1680)));
    return k * std::log1p(d / k) - d - 0.5 * std::log(2 * kPi * k) - r;
  }

 private:
  static constexpr double kInversionBelow = 10;  // PTRS needs mu >= 10
  static constexpr double kPi = 3.14159265358979323846;
  double mu_ = 0;
  double exp_neg_mu_ = 1;                           // inversion
  double b_ = 0, a_ = 0, inv_alpha_ = 0, v_r_ = 0;  // PTRS constants (log mu only in the rare exact test)
};

// Two independent standard normals from one pair of uniforms: Marsaglia's polar method (a
// uniform point in the unit disc, s = |point|^2, scaled by sqrt(-2 ln s / s)); one log and one
// sqrt per pair, no trigonometry, about 1.27 trials.
inline void standard_normal_pair(pcg32& rng, double& z1, double& z2) {
  for (;;) {
    const double x = 2 * uniform_open01(rng) - 1, y = 2 * uniform_open01(rng) - 1;
    const double s = x * x + y * y;
    if (s >= 1 || s == 0) continue;
    const double f = std::sqrt(-2 * std::log(s) / s);
    z1 = x * f;
    z2 = y * f;
    return;
  }
}

}  // namespace rangesim::systemc
