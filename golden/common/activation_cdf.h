#pragma once
// Probability that a noisy pixel has reached a threshold: the building block of the closed-form
// noise model (position_noise.h, detect.h).
//
// Noise model per pixel and frame:
//  - shot noise: the integrated photo-electrons (signal + background + dark) are a Poisson process
//    N(t) with mean mu(t) = C v(t) / q;
//  - kTC reset noise sqrt(kT/C), sampled once at reset and then frozen for the frame;
//  - read noise of the source follower / comparator, 1/f-dominated at microsecond scale, hence a
//    static offset for the frame as well.
// The two static terms add to R ~ Normal(0, sigma_R^2). Since N(t) only grows and R is fixed, a pixel
// that is activated stays activated (the latch enforces it too) and
//   P(activated by t) = P(N(t) + R_e >= theta_e) = sum_n Pois(n; mu) Phi((n - theta_e) / sigma_e)
// in electrons (R_e = R C / q, theta_e = (theta / A_sf) C / q).
//
// Evaluation: the Poisson pmf is summed by recurrence from its mode (started in log space) over
// mu +- (13 sqrt(mu) + 20), outside of which its mass is < 1e-30; Phi is evaluated only where
// |z| < 9 (Phi(-9) = 1.1e-19) and is exactly 0 or 1 beyond. Both P and 1 - P are accumulated as
// separate sums so either is accurate when tiny. Cheap Chernoff bounds return 0 or 1 directly when
// the answer is within 1e-18 of it. Absolute error < 1e-15.
#include <cstddef>
#include <vector>

namespace rangesim::golden {

struct ActivationProbability {
  double p = 0;  // P(activated)
  double q = 1;  // 1 - p, accurate when p is close to 1
};

// P(n + R_e >= threshold_e) with n ~ Poisson(mean_e), R_e ~ Normal(0, sigma_e^2); sigma_e = 0 gives
// the Poisson upper tail P(n >= ceil(threshold_e)).
ActivationProbability activation_probability(double mean_electrons, double threshold_electrons, double sigma_electrons);

// The same for many means at one threshold and noise (an operating point's pixels and samplings):
// the band's Phi((n - t) / s) depends on n - t only, so it is tabulated once at the integers of
// the band and looked up, which removes the erfc per term (three quarters of the golden
// evaluation's time). Bit for bit activation_probability (the same terms summed in the same order).
class ActivationTable {
 public:
  ActivationTable(double threshold_electrons, double sigma_electrons);
  ActivationProbability operator()(double mean_electrons) const;
  double threshold() const { return t_; }
  double sigma() const { return s_; }
  std::size_t entries() const { return split_.size(); }  // its memory, in band entries

 private:
  double t_ = 0, s_ = 0;
  double first_ = 0;                          // first integer of the band t - 9 s < n < t + 9 s
  std::vector<ActivationProbability> split_;  // P(n + R >= t) and its complement at n = first_ + i
};

}  // namespace rangesim::golden
