#include "golden/common/spot.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace rangesim::golden {

double spot_sigma_px(const SpotConfig& spot) { return spot.sigma_per_fwhm * spot.fwhm_px; }

double spot_profile(const SpotConfig& spot, double distance_px) {
  const double s = spot_sigma_px(spot);
  return std::exp(-distance_px * distance_px / (2 * s * s));
}

double spot_half_width_px(const SpotConfig& spot, double level) {
  if (level <= 0) return std::numeric_limits<double>::infinity();
  if (level > 1) return -1.0;
  return spot_sigma_px(spot) * std::sqrt(-2.0 * std::log(level));
}

double spot_window_half_width_px(const SpotConfig& spot) { return spot_half_width_px(spot, kSpotWindowLevel); }

ColumnSpan spot_window(const SpotConfig& spot, double x0_px, int columns) {
  const double h = spot_window_half_width_px(spot);
  ColumnSpan w;
  w.first = static_cast<int>(std::max(0.0, std::ceil(x0_px - h)));
  w.last = static_cast<int>(std::min(static_cast<double>(columns - 1), std::floor(x0_px + h)));
  return w;
}

}  // namespace rangesim::golden
