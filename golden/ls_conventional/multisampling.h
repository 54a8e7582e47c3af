#pragma once
// Noise-free multi-sampling estimate of the spot centre and its exact quantisation error.
//
// Per sampling k with at least one activated pixel:
//   1 bit:  centre_k = (l_k + r_k) / 2, the leftmost / rightmost activated pixel (edge centre);
//   b bits: centre_k = code-weighted centroid sum(c_i x_i) / sum(c_i).
// The combined sub-pixel centre is the mean of centre_k over the samplings with a detection;
// none -> no detection. Activations are nested in time (swings only rise, and the latch keeps a
// pixel activated), so the activation count of a pixel scales with its intensity (thesis Fig. 2.3).
//
// As a function of the spot centre x0 the estimate is piecewise constant: it changes only where a
// pixel crosses a code level, x0 = x_i +- h_{k,m}. The error e(x0) = xhat - x0 is therefore
// linear (slope -1) between these breakpoints and its mean square over one pixel is integrated
// exactly, segment by segment.
#include <vector>

#include "golden/ls_conventional/centroid.h"
#include "golden/common/row_model.h"

namespace rangesim::golden {

// Estimate from the half-widths (the form the analytic results use).
CentreEstimate noise_free_estimate(const RowModel& row, double x0_px);

// Same estimate by brute force: every pixel's swing -> quantise -> centroid.h. Slow; for tests.
CentreEstimate direct_estimate(const RowModel& row, double x0_px);

// Centre of one sampling k (1..N), from the half-widths.
CentreEstimate sampling_estimate(const RowModel& row, double x0_px, int k);

struct QuantisationError {
  double rms_px = 0;              // sqrt of the mean e^2 over the detected part of the pixel
  double resolution_px = 0;       // mean step of xhat as the spot crosses one pixel: 1 px / number of jumps
                                  // (thesis "sub-pixel resolution": 0.5 px for binary single sampling)
  double equivalent_step_px = 0;  // sqrt(12) rms: step of the uniform quantiser with the same rms error
  double worst_px = 0;            // sup |e| over the detected part
  double largest_step_px = 0;     // largest jump of xhat between adjacent segments (thesis "sub-pixel resolution")
  double detected_fraction = 0;   // part of the pixel where some sampling detects (noise-free)
  int segments = 0;               // pieces of constant xhat in the pixel
};

// x0 uniform over [c - 0.5, c + 0.5], exact over the breakpoints.
QuantisationError quantisation_error(const RowModel& row);

// The breakpoints x0 = j +- h_{k,m} inside [lo, hi], sorted, with lo and hi included.
std::vector<double> estimate_breakpoints(const RowModel& row, double lo_px, double hi_px);

}  // namespace rangesim::golden
