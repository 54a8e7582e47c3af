#pragma once
// Closed-form mean and variance of the multi-sampling centre estimate under noise.
//
// 1 bit (exact). Each pixel j has a first activated sampling F_j in {1..N, never = N+1} with
// P(F_j <= k) = activation_probability at t_k (activation_cdf.h); pixels are independent. The
// estimate depends only on the F_j: with m = min_j F_j, the samplings with a detection are
// D = {m..N}; l_k = min{j : F_j <= k}, r_k = max{j : F_j <= k}; xhat = mean_{k in D} (l_k + r_k)/2.
// Conditioning on m = a (as 1{min F >= a} - 1{min F >= a+1}), every needed expectation
// E[l_k], E[l_k l_k'], E[l_k r_k'], E[r_k r_k'] on {min F >= lb} is a sum over one or two pixel
// indices of products over pixels of P(F_j in [lo_j, hi_j]); running prefix/suffix products and
// running sums make each O(W) for a window of W pixels. The window holds the pixels whose
// activation probability by t_N exceeds 1e-15; the others are taken as never activated.
//
// b > 1 bits (approximate, flagged): first-order (delta-method) propagation of the code noise
// through the code-weighted centroids. Expected codes and code variances per pixel and sampling
// are exact; the correlation of one pixel's codes across samplings is taken from the Gaussian
// correlation of its analog noise (shared static offset, nested shot noise); the samplings in D
// are those that detect with probability >= 1/2. P(detect) is exact.
#include <map>
#include <utility>
#include <vector>

#include "golden/common/activation_cdf.h"
#include "golden/common/row_model.h"

namespace rangesim::golden {

struct PositionMoments {
  double p_detect = 0;    // P(some sampling detects)
  double mean_px = 0;     // E[xhat | detect], absolute pixel coordinate
  double var_px2 = 0;     // Var[xhat | detect]
  bool exact = true;      // false: delta-method approximation (adc_bits > 1)
  int window_pixels = 0;  // pixels with activation probability > 1e-15
};

// Memoises activation probabilities within one operating point (background-only pixels share one
// value; they are the many) and computes the others from an ActivationTable per threshold.
class ActivationCache {
 public:
  ActivationProbability get(double mean_e, double threshold_e, double sigma_e);

 private:
  std::map<std::pair<double, double>, ActivationProbability> memo_;
  // One table per (threshold, sigma) seen: a code level each. All are kept (a multi-bit ADC cycles
  // through up to 255 levels per pixel, and evicting by count rebuilt a table on every call) up to
  // kMaxTableEntries band entries (32 MB), then dropped together.
  std::map<std::pair<double, double>, ActivationTable> tables_;
  std::size_t table_entries_ = 0;
  static constexpr std::size_t kMaxTableEntries = std::size_t{1} << 21;
};

// Exact moments of the 1-bit edge-centre estimate. cdf[j][k] = P(F_j <= k) and surv[j][k] =
// P(F_j > k) for k = 0..N+1 (cdf[j][0] = 0, cdf[j][N+1] = 1); x[j] = pixel positions (ascending).
// mean_px is returned in the coordinates of x.
PositionMoments edge_centre_moments(const std::vector<double>& x, const std::vector<std::vector<double>>& cdf,
                                    const std::vector<std::vector<double>>& surv, int N);

// Moments at spot centre x0 for the row's operating point (exact for 1 bit, delta for more).
PositionMoments position_moments(const RowModel& row, double x0_px, ActivationCache* cache = nullptr);

// The same split at the spot's pixels (golden/common/spot.h, spot_window): an outlier is an
// activation of a pixel outside them by t_N. The pixels are independent, so given no outlier the
// estimate is that of the spot's pixels alone, exactly (1 bit; adc_bits > 1: clean = all, delta).
struct SplitMoments {
  PositionMoments all;    // every activation (position_moments)
  PositionMoments clean;  // given no outlier; p_detect = P(detect | no outlier)
  double p_outlier = 0;   // P(some pixel outside the spot's pixels activates by t_N)
};
SplitMoments position_moments_split(const RowModel& row, double x0_px, ActivationCache* cache = nullptr);

// Pixel-input threshold of code level m, sigma of the static noise and the shot-noise mean, in
// electrons: the quantities activation_probability() is called with (exposed for Monte Carlo).
double level_threshold_electrons(const RowModel& row, int m);
double static_noise_electrons(const RowModel& row);

}  // namespace rangesim::golden
