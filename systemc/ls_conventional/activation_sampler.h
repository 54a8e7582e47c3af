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
//
// Inversion (config simulation.inversion_draw; shot and static noise on, saturation harmless as
// above): P(K <= k) = f(lambda_k) exactly (the comparator input only grows while o and r stay
// frozen), so with one uniform u, K = the first k with u < f(lambda_k), never if none. A lambda_k
// at or below lambda_lo counts as f = 0 and at or above lambda_hi as f = 1 (the certain outcomes'
// own 2^-56 per end). In between, u is compared with the threshold's ActivationTable
// (activation_table.h): |f~ - f| <= bound, so u < f~ - bound and u >= f~ + bound decide as golden's
// f would; only the rest (~2e-5 of the comparisons) evaluates golden::activation_probability
// itself. The decision is therefore that of u < f(lambda_k) with golden's f (absolute error
// < 1e-15) whether or not the table exists yet: it is made after a threshold's first few exact
// evaluations, so a threshold used for a handful of pixels never pays for one. u is the pixel's
// keyed_uniform (systemc/common/random_stream.h), the same for any visiting order or thread.
// Saturation that can matter, or no static noise: the Gamma draw above.
#include <cstdint>
#include <memory>
#include <vector>

#include <pcg_random.hpp>

#include "golden/common/activation_cdf.h"
#include "systemc/ls_conventional/activation_table.h"

namespace rangesim::systemc {

constexpr double kComputedTail = 1e-17;                  // classification level of the computed tails
constexpr double kCertainTail = 1.3877787807814457e-17;  // 2^-56: bound on the true tail, per end

// The pixel's noise and comparator, fixed for a kernel.
struct ActivationModel {
  bool shot = true;              // Poisson electrons (else the deterministic swing)
  double ktc_V = 0, read_V = 0;  // rms of the static noise terms (0: switched off)
  double electrons_per_V = 0;    // c = C / q
  double gain = 1;               // A_sf
  double saturation_V = 0;       // V_sat
  int samplings = 1;             // N
};

// What a pixel gets in one frame access (the per-pixel inputs of the pixel array).
struct PixelDrive {
  double signal_V = 0, profile = 0, background_V = 0, dark_V = 0;
  double mean_step_e = 0;  // m = mu(T) / N (shot noise on)
};

// Mean electron counts (lambda) bounding the certain outcomes at one comparator threshold.
struct ActivationBounds {
  double never_upto_e = -1;          // lambda <= this: P(fired) <= kComputedTail (-1: none)
  double always_from_e = 1e300;      // lambda >= this: P(not fired) <= kComputedTail (1e300: none)
  bool saturation_harmless = false;  // P(A (V_sat + r) < theta) <= 1e-19: f without saturation is exact
  bool invertible = false;           // the inversion applies: shot and static noise, saturation harmless, a table fits
};

// What the sampler keeps per comparator threshold: its bounds and, once it has been used for a few
// draws, its table of f for the inversion.
struct ThresholdEntry {
  double threshold_V = 0;
  ActivationBounds b;
  std::shared_ptr<const ActivationTable> table;  // made after kTableAfter exact evaluations, or shared
  int exact_evaluations = 0;               // golden::activation_probability calls at this threshold
  // f itself, bit for bit golden::activation_probability with the band's Phi looked up (shot and
  // static noise on; else null): an exact evaluation sums ~1,100 Poisson terms at the preset's
  // threshold, and each one's erfc made it 35 us, ten times a map between the table's cuts and
  // about thirty times in the bounds' bisection. Made with the entry (one erfc per integer of the
  // band, about two evaluations' worth).
  std::shared_ptr<const golden::ActivationTable> exact;
};

class ExactActivation {
 public:
  explicit ExactActivation(const ActivationModel& model);

  static constexpr int kTableAfter = 8;  // exact evaluations at a threshold before its table is made

  // Bounds (and table) at threshold theta (comparator input, V); a small memo (rows share
  // thresholds). A reference stays valid until the next call. Both are pure functions of the model
  // and theta, so they are also kept for the whole process (thread-safe): another kernel with the
  // same model (the next map, another row band's thread, a Monte Carlo trial) takes them from there.
  ThresholdEntry& entry(double threshold_V);
  const ActivationBounds& bounds(double threshold_V) { return entry(threshold_V).b; }
  // f(lambda) and 1 - f(lambda) at the entry's threshold, the pixel's exact activation probability.
  void probability(double lambda_e, const ThresholdEntry& e, double& p, double& q) const;

  // Mean electron count by sampling k of the pixel (the quantity the bounds are in).
  double lambda_e(const PixelDrive& d, int k) const;
  // The certain first firing sampling (0: never) or -1 if the outcome is random.
  int certain_first_firing(const PixelDrive& d, const ActivationBounds& b) const;
  // A draw of the first firing sampling (0: never) from the pixel's stream (positioned at its start).
  int draw_first_firing(const PixelDrive& d, double threshold_V, pcg32& rng) const;

  // Whether invert_first_firing applies at this threshold: shot and static noise on, saturation harmless.
  static bool inversion_applies(const ThresholdEntry& e) { return e.b.invertible; }
  // The first firing sampling (0: never) by inversion with the uniform u in (0, 1).
  int invert_first_firing(const PixelDrive& d, ThresholdEntry& e, double u);
  // u < f(lambda) at the entry's threshold, decided as with golden's f (table or not).
  bool below(double u, double lambda_e, ThresholdEntry& e);
  // The inversion of one pixel prepared for many uniforms (rows with the same drive): per sampling
  // k, cut[2(k-1)] and cut[2(k-1)+1] with u below the first: fired by k, at or above the second: not
  // (f~ -+ bound; 0, 0 for f = 0; 2, 2 for f = 1; -1, 2 before the table exists). Then
  // invert_prepared(d, e, cut, u) == invert_first_firing(d, e, u) for every u.
  void prepare_inversion(const PixelDrive& d, const ThresholdEntry& e, double* cut) const;
  int invert_prepared(const PixelDrive& d, ThresholdEntry& e, const double* cut, double u) {
    for (int k = 1; k <= m_.samplings; ++k) {
      const double a = cut[2 * (k - 1)], b = cut[2 * (k - 1) + 1];
      if (u < a) return k;
      if (u >= b) continue;
      if (below(u, lambda_e(d, k), e)) return k;
    }
    return 0;
  }
  // Exact evaluations since construction (the inversion's fallbacks and the tables' first uses).
  long long exact_evaluations() const { return exact_evaluations_; }

 private:
  ActivationBounds compute_bounds(const ThresholdEntry& e) const;
  bool fires(double n_e, double offset_V, double read_V, double threshold_V) const;

  ActivationModel m_;
  double sigma_V_ = 0;  // rms of o + r
  std::vector<ThresholdEntry> memo_;
  long long exact_evaluations_ = 0;
};

}  // namespace rangesim::systemc
