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

}  // namespace rangesim::golden
