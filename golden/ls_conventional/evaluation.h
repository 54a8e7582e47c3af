#pragma once
// The thesis's evaluation of ls-conventional (chapter 3.1) over a signal x background grid,
// with its faults fixed (ARCHITECTURE.md, "Known thesis faults"): detectable area with the reason where range cannot be
// derived, accuracy (pixel pitch and metres), SBR' by both definitions, dynamic ranges.
#include <string>
#include <vector>

#include "core/ls_conventional/config.h"

namespace rangesim::golden {

// Why range can or cannot be derived at an operating point.
enum class Detect {
  Detectable,            // peak activates, not saturated, background alone does not activate
  BelowThreshold,        // signal + background at the peak stays below V_cmp
  Saturated,             // V_sig + V_bg > V_sat: activated, but accuracy is not controlled
  BackgroundActivation,  // background alone activates pixels of the row
};
const char* to_string(Detect d);  // "detectable", "below_threshold", "saturated", "background_activation"

struct OperatingPoint {
  double signal_V = 0;      // V_sig at the spot peak, end of integration (eq. 3.1)
  double background_V = 0;  // V_bg, end of integration
  Detect detect = Detect::BelowThreshold;
  double sbr_total_dB = 0;  // eq. 3.11: 20 log10((V_sig + V_bg) / V_bg)
  double sbr_ratio_dB = 0;  // eq. 3.23 / 4.11: 20 log10(V_sig / V_bg)
  // Accuracy, averaged over spot positions uniformly across one pixel (valid when detectable):
  double quantisation_rms_px = 0;  // rms of the noise-free estimate's error (exact)
  double resolution_px = 0;   // mean step of the estimate as the spot crosses one pixel (thesis "sub-pixel resolution")
  double worst_error_px = 0;  // largest noise-free error over the spot positions
  double noise_std_px = 0;    // p-weighted rms over positions of the estimate's std from noise (closed form)
  double accuracy_px = 0;     // rms total error given detection: sqrt(mean(p (bias^2 + variance)) / mean(p))
  double accuracy_m = 0;      // accuracy_px mapped to range by triangulation at optics.distance_m
  double p_detect = 0;        // probability that the row reports a centre, mean over spot positions (exact)
  // Outliers (golden/common/spot.h): an activation outside the spot's pixels, a false activation of
  // the background that moves an edge by up to the row's width.
  double accuracy_clean_px = 0;  // rms error of the detecting frames without an outlier
  double accuracy_clean_m = 0;   // the same in metres
  double p_outlier = 0;          // probability of an outlier per frame, mean over spot positions
  // Added by the golden model (see subpixel_average.h for how each is computed):
  double largest_step_px = 0;          // largest jump of the noise-free estimate (thesis "sub-pixel resolution")
  double detected_fraction = 0;        // part of the pixel where the noise-free readout detects the spot
  bool noise_exact = true;             // false: noise moments by the delta method (adc_bits > 1), approximate
  const char* noise_method = "exact";  // "exact" or "delta"
  // The noise-free readout detects at none of the spot positions (the detection edge): every
  // detection comes from noise.
  bool noise_only_detections = false;
  int subpixel_positions = 0;          // spot positions the average over a pixel used
  double subpixel_error_estimate = 0;  // its estimated relative error (NaN: the fixed rule)
  bool subpixel_converged = true;      // the estimate met evaluation.subpixel_tolerance
};

struct DynamicRange {
  double lo_V = 0, hi_V = 0;        // edges of the detectable interval (exact, not grid-limited below the grid max)
  double range_dB = 0;              // 20 log10(hi / lo); 0 when nothing is detectable
  bool hi_limited_by_grid = false;  // true when the upper edge is the grid's end
  bool lo_limited_by_grid = false;  // true when the lower edge is the grid's start (detectable there)
};

struct EvaluationSummary {
  int samplings = 0;
  int adc_bits = 0;
  int points_total = 0;
  int points_detectable = 0;
  DynamicRange signal;                                // detectable signal at the grid's lowest background
  DynamicRange background;                            // detectable background at the grid's highest signal
  double sbr_min_dB = 0, sbr_max_dB = 0;              // eq. 3.11 over the detectable area
  double sbr_ratio_min_dB = 0, sbr_ratio_max_dB = 0;  // eq. 3.23 over the detectable area
  double accuracy_min_px = 0, accuracy_max_px = 0;    // over the detectable area
  double accuracy_min_m = 0, accuracy_max_m = 0;
  double range_per_px_m = 0;  // range change per pixel of image position at optics.distance_m
};

struct Evaluation {
  std::vector<double> signal_V;        // grid axis, ascending
  std::vector<double> background_V;    // grid axis, ascending
  std::vector<OperatingPoint> points;  // row-major: points[ib * signal_V.size() + is]
  EvaluationSummary summary;
  const OperatingPoint& at(size_t ib, size_t is) const { return points[ib * signal_V.size() + is]; }
};

// Log-spaced axis; n = 1 gives {lo}.
std::vector<double> log_axis(double lo, double hi, int n);

// Evaluates one operating point.
OperatingPoint evaluate_point(const LsConventionalConfig& cfg, double signal_V, double background_V);

// Exact edges of the detectable interval: signal at a fixed background, background at a fixed
// signal, clipped to [lo_limit, hi_limit] (the grid's span).
DynamicRange signal_dynamic_range(const LsConventionalConfig& cfg, double background_V, double lo_limit_V,
                                  double hi_limit_V);
DynamicRange background_dynamic_range(const LsConventionalConfig& cfg, double signal_V, double lo_limit_V,
                                      double hi_limit_V);

// Evaluates the grid cfg.grid; `progress(done, total)` is called now and then when set.
Evaluation evaluate(const LsConventionalConfig& cfg, void (*progress)(int done, int total) = nullptr);

}  // namespace rangesim::golden
