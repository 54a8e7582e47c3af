#pragma once
// Gaussian sheet-beam profile across a row (thesis eq. 3.6), peak normalised to 1.
//
// sigma = sigma_per_fwhm * FWHM. The exact Gaussian factor is 1 / (2 sqrt(2 ln 2)) = 0.4247; the
// thesis writes 0.45 (a typo). Both are a preset value (spot.sigma_per_fwhm).
#include "core/ls_conventional/config.h"

namespace rangesim::golden {

// sigma of the Gaussian in pixels.
double spot_sigma_px(const SpotConfig& spot);

// g(d) = exp(-d^2 / (2 sigma^2)), d = x_i - x0 in pixels.
double spot_profile(const SpotConfig& spot, double distance_px);

// Largest |d| with g(d) >= level: sigma sqrt(-2 ln level). Returns +infinity for level <= 0
// (every pixel reaches it) and a negative value for level > 1 (no pixel reaches it).
double spot_half_width_px(const SpotConfig& spot, double level);

// The spot's pixels: those within spot_window_half_width_px of its centre, where the profile is at
// least kSpotWindowLevel of its peak. Farther out a pixel's signal is below 1e-12 of the peak's (at
// 1.5 V, 1.5 pV against millivolts of noise), so it behaves as a background-only pixel, and an
// activation there is an outlier: a false activation of the background, which moves an edge by up
// to the row's width. Golden and the Monte Carlo count outliers apart from the accuracy of the
// frames without one (docs/evaluate-montecarlo.md, "Outliers").
inline constexpr double kSpotWindowLevel = 1e-12;
double spot_window_half_width_px(const SpotConfig& spot);

// Columns [first, last] of the spot's pixels for a spot centred at x0 in a row of `columns`
// pixels (pixel i at x = i); first > last when none is in the row.
struct ColumnSpan {
  int first = 0, last = -1;
  bool contains(int column) const { return column >= first && column <= last; }
};
ColumnSpan spot_window(const SpotConfig& spot, double x0_px, int columns);

}  // namespace rangesim::golden
