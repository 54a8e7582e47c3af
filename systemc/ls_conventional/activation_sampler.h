#pragma once
// Exact activation sampling of the ls-conventional pixel (the pixel array's default path,
// preset key simulation.exact_activation_sampling): instead of drawing every pixel's noise and
// comparing it at each sampling, each pixel's first firing sampling K (1..N, or never) is drawn
// from its exact distribution, and pixels whose K is certain to double precision draw nothing.
//
// The model is the pixel array's (pixel_array_kernel.h): static noise o (kTC) and r (read) frozen
// for the frame access, electrons n(t) a Poisson process of mean lambda(t) (per sampling m = mu(T)/N),
// comparator A (min(n / c + o, V_sat) + r) >= theta at t_k, latched. The comparator is monotone in n,
// so given (o, r) the pixel fires at the first k with n(t_k) >= n*, n* the smallest count for which
// the comparator's own double expression is true (none: never, e.g. saturated below theta). A Poisson
// process reaches n* at the mean "time" T ~ Gamma(n*, 1) (its n*-th arrival), so
//   K = max(1, ceil(T / m)), never if K > N.
// That is exact in distribution: the same two normals as the per-sampling path (the first draws of
// the pixel's keyed stream, so o and r are the very same values), then one Gamma variate instead of
// N Poisson counts. Without shot noise the pixel's swings are deterministic and K is found with the
// per-sampling path's own expressions (bit-identical to it pixel for pixel).
//
// Certain outcomes: with f(lambda) = P(n + c (o + r) >= c theta / A) (golden::activation_probability;
// without shot noise Phi), a pixel with lambda_k <= lambda_lo or >= lambda_hi at every k has one
// outcome with probability > 1 - 2 kCertainTail. lambda_lo / lambda_hi are found by bisection
// where the computed tail is <= kComputedTail (1e-17); activation_probability's tails are within
// 2e-19 of the truth, and tests/skipping/test_exact_activation.cpp checks the true tail at both
// bounds against an independent long-double sum: < kCertainTail = 2^-56 (1.4e-17) per pixel and
// end, so a map's 1.4 M classified pixels differ from exact sampling with probability < 4e-11.
// Saturation only makes firing less likely: lambda_lo stays an upper bound; lambda_hi is used only
// when P(A (V_sat + r) < theta) <= 1e-19 on the row.
#include <cstdint>
#include <vector>

#include <pcg_random.hpp>

namespace rangesim::systemc {

constexpr double kComputedTail = 1e-17;             // classification level of the computed tails
constexpr double kCertainTail = 1.3877787807814457e-17;  // 2^-56: bound on the true tail, per end

// The pixel's noise and comparator, fixed for a kernel.
struct ActivationModel {
  bool shot = true;             // Poisson electrons (else the deterministic swing)
  double ktc_V = 0, read_V = 0;  // rms of the static noise terms (0: switched off)
  double electrons_per_V = 0;   // c = C / q
  double gain = 1;              // A_sf
  double saturation_V = 0;      // V_sat
  int samplings = 1;            // N
};

// What a pixel gets in one frame access (the per-pixel inputs of the pixel array).
struct PixelDrive {
  double signal_V = 0, profile = 0, background_V = 0, dark_V = 0;
  double mean_step_e = 0;  // m = mu(T) / N (shot noise on)
};

// Mean electron counts (lambda) bounding the certain outcomes at one comparator threshold.
struct ActivationBounds {
  double never_upto_e = -1;       // lambda <= this: P(fired) <= kComputedTail (-1: none)
  double always_from_e = 1e300;   // lambda >= this: P(not fired) <= kComputedTail (1e300: none)
};

class ExactActivation {
 public:
  explicit ExactActivation(const ActivationModel& model);

  // Bounds at threshold theta (comparator input, V); a small memo (rows share thresholds).
  const ActivationBounds& bounds(double threshold_V);
  // f(lambda) and 1 - f(lambda) at threshold theta, the pixel's exact activation probability.
  void probability(double lambda_e, double threshold_V, double& p, double& q) const;

  // Mean electron count by sampling k of the pixel (the quantity the bounds are in).
  double lambda_e(const PixelDrive& d, int k) const;
  // The certain first firing sampling (0: never) or -1 if the outcome is random.
  int certain_first_firing(const PixelDrive& d, const ActivationBounds& b) const;
  // A draw of the first firing sampling (0: never) from the pixel's stream (positioned at its start).
  int draw_first_firing(const PixelDrive& d, double threshold_V, pcg32& rng) const;

 private:
  ActivationBounds compute_bounds(double threshold_V) const;
  bool fires(double n_e, double offset_V, double read_V, double threshold_V) const;

  ActivationModel m_;
  double sigma_V_ = 0;  // rms of o + r
  struct Memo {
    double threshold_V;
    ActivationBounds b;
  };
  std::vector<Memo> memo_;
};

}  // namespace rangesim::systemc
