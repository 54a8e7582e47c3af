#pragma once
// Whether one measured histogram holds an echo: the validity flag and confidence of a tof-spad
// range-map pixel. The counts in the estimator's peak window are tested against the background
// level the same histogram shows outside the window (per armed cycle, so pile-up's falling
// armed counts are followed); the p-value of the excess is Poisson and corrected for the peak
// search over every code, then read as Gaussian sigma. The pixel is valid at
// evaluation.detection_sigma, the k of the golden detection criterion (window signal counts above
// k sqrt(background counts)), here applied to one histogram without knowing the rates.
#include "golden/tof_spad/estimator.h"

namespace rangesim::golden::spad {

struct PeakSignificance {
  int peak_bin = -1;
  Window window;
  double window_counts = 0;      // events in the window
  double background_counts = 0;  // expected there from the level outside it
  double sigma = 0;              // Gaussian-equivalent significance of the excess, after the peak search
};

// One histogram. A histogram without events has significance 0.
PeakSignificance peak_significance(const HistogramCounts& h, const EstimatorConfig& cfg);
// The same with the peak code already known (peak_bin(h, cfg), e.g. from estimate_time_s).
PeakSignificance peak_significance(const HistogramCounts& h, const EstimatorConfig& cfg, int peak);

}  // namespace rangesim::golden::spad
