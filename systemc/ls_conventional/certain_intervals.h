#pragma once
// A row's certain pixels as intervals of the distance from the spot centre (the pixel array's exact
// path inside the sparse window; config simulation.certain_intervals): instead of comparing every
// window pixel's mean counts with the bounds of activation_sampler.h, the distances at which they
// meet the bounds, once per row drive (signal, background, threshold); only the pixels between
// (the band) get per-pixel work.
//
// On a row the mean count of pixel i by sampling k is lambda_k(d) = c (S g(d) + B + D) k / N,
// d = |i - x0|, g(d) = exp(-d^2 / (2 sigma^2)) falling with d. So
//   lambda_k(d) >= lambda_hi  <=>  d <= r_k   (certainly fired by k),
//   lambda_k(d) <= lambda_lo  <=>  d >= s_k   (certainly not fired by k),
// g(r_k) = (lambda_hi N / (k c) - B - D) / S and g(s_k) the same at lambda_lo; both grow with k.
// The per-pixel rule (ExactActivation::certain_first_firing: the first k with lambda_k >= lambda_hi,
// all earlier ones <= lambda_lo) gives K = 1 for d in [0, r_1], K = k for d in [s_{k-1}, r_k], never
// for d >= s_N; every other d lies in a gap (r_k, s_k), a band pixel.
//
// The bound (tests/skipping/test_certain_intervals.cpp): each lambda bound is moved inward by
// kMargin = 1e-10 of itself, and each distance by kMargin of itself, far beyond the rounding of the
// per-pixel lambda (< 1e-13 relative, the exp of arguments up to 40 included); r_k is then made
// non-decreasing from above (min over j >= k) and s_k from below (max over j <= k). All of this
// only shrinks the certain sets, so a pixel certain here is certain with the same K by the
// per-pixel rule, and a pixel within the margins is a band pixel, which the per-pixel rule decides
// one by one: the switch changes no bit (tested on the plane map and random rows).
#include <limits>
#include <vector>

#include "core/ls_conventional/config.h"
#include "systemc/ls_conventional/activation_sampler.h"

namespace rangesim::systemc {

struct RowCertainty {
  static constexpr double kAll = std::numeric_limits<double>::infinity();
  // Per sampling k = 1..N at index k - 1: r_k (-1: no pixel, kAll: every pixel) and s_k (kAll: no
  // pixel, 0: every pixel).
  std::vector<double> fired_within, never_beyond;
  // The certain first firing sampling 1..N, 0 for certainly never, -1 for a band pixel.
  int classify(double d) const {
    for (std::size_t k = 0; k < fired_within.size(); ++k) {
      if (d <= fired_within[k]) return static_cast<int>(k) + 1;
      if (d < never_beyond[k]) return -1;
    }
    return 0;
  }
};

class CertainIntervals {
 public:
  static constexpr double kMargin = 1e-10;

  CertainIntervals(const SpotConfig& spot, double dark_V, double electrons_per_V, int samplings);

  // The distances of a row of spot-peak swing signal_V over background_V at bounds b (a one-entry
  // memo: the rows of a plane share them). A reference valid until the next call.
  const RowCertainty& of(double signal_V, double background_V, const ActivationBounds& b);
  void compute(double signal_V, double background_V, const ActivationBounds& b, RowCertainty& out) const;

 private:
  double fired_distance(double need_V, double signal_V, double base_V) const;
  double never_distance(double cap_V, double signal_V, double base_V) const;

  double two_sigma2_ = 0, dark_V_ = 0, electrons_per_V_ = 0;
  int samplings_ = 1;
  bool have_memo_ = false;
  double memo_signal_V_ = 0, memo_background_V_ = 0, memo_lo_e_ = 0, memo_hi_e_ = 0;
  RowCertainty memo_;
};

}  // namespace rangesim::systemc
