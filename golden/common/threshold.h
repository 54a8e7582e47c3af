#pragma once
// Comparisons against a detection threshold that do not flip on the last bits of the arithmetic.
//
// An operating point defined exactly at a threshold (the thesis's own point: 0.01 V signal over
// 0.001 V background, where A (V_sig + V_bg + V_dark) and theta = A (V_bg + V_dark) + Delta V_ADC
// are the same number computed two ways) must be classed the same whichever way rounding falls.
// A value within kThresholdRelTol of the threshold therefore reaches it. 1e-9 is far above the
// ~1e-15 relative error of these few operations and far below any physical resolution of a
// threshold (a 10 mV step resolved to 10 fV).
#include <algorithm>
#include <cmath>

namespace rangesim::golden {

inline constexpr double kThresholdRelTol = 1e-9;

// value >= threshold, up to rounding.
inline bool reaches_threshold(double value, double threshold) {
  return value >= threshold - kThresholdRelTol * std::max(std::fabs(value), std::fabs(threshold));
}

// value < threshold, up to rounding (the complement of reaches_threshold).
inline bool below_threshold(double value, double threshold) { return !reaches_threshold(value, threshold); }

}  // namespace rangesim::golden
