#pragma once
// The noise part of ls-conventional's accuracy: the exact moments of the estimate at a spot centre
// x0 (golden/common/position_noise.h) averaged over x0 uniform across one pixel, as a Monte Carlo
// with the spot drawn uniformly measures them.
//
// What is averaged (u = x0 - c + 0.5 in [0, 1]; p, b = E[xhat] - x0, v = Var given detection):
//   P(detect)       = mean_u p
//   accuracy^2      = mean_u[p (b^2 + v)] / mean_u p          (rms error given detection)
//   clean accuracy^2 = the same over the frames without an outlier (an activation outside the
//                     spot's pixels, golden/common/spot.h), p -> (1 - p_out) p_clean
//   P(outlier)      = mean_u p_out
// Each weighted by p: at the detection edge p is between 0 and 1 and varies with u, and only the
// detecting frames carry an error (exact there, not only where the noise-free readout detects).
//
// Control variate: the noise-free readout's 1{detects}(u) and e_nf(u)^2 are integrated exactly
// between their breakpoints (multisampling.h), so the quadrature carries only what noise changes,
// p - 1{nf} and p (b^2 + v) - 1{nf} e_nf^2, which vanish away from the breakpoints as the noise
// vanishes.
//
// Quadrature: adaptive Gauss-Kronrod (7-15 points) on the segments between the noise-free
// breakpoints, where the integrand's near-steps sit at the segment ends; the segment with the
// largest error estimate |K15 - G7| is halved until the estimated relative error of the accuracies
// and of P(detect) (and of P(outlier), or 1e-9 absolute) is at most `tolerance`, or the positions
// reach `max_positions` (then converged = false). A symmetric row (as many pixels each side of the
// centre pixel) gives mirrored estimates at u and 1 - u: only u <= 1/2 is integrated.
// tolerance = 0: a fixed midpoint rule of `fixed_positions` positions averaging p and p (b^2 + v)
// themselves (fast, not converged; no control variate, which a few positions can push out of [0, 1]).
#include "golden/common/row_model.h"
#include "golden/ls_conventional/multisampling.h"

namespace rangesim::golden {

struct SubpixelAverage {
  double p_detect = 0;                 // mean over positions of P(detect)
  double accuracy_px = 0;              // rms error given detection
  double accuracy_clean_px = 0;        // rms error given detection and no outlier
  double p_outlier = 0;                // mean over positions of P(an activation outside the spot's pixels)
  double noise_std_px = 0;             // p-weighted rms over positions of the std given detection
  double error_estimate = 0;           // estimated relative error of the averages (the criterion's value)
  int positions = 0;                   // spot positions evaluated
  bool converged = true;               // the error estimate met the tolerance
  bool noise_only_detections = false;  // the noise-free readout detects at no position
};

SubpixelAverage subpixel_average(const RowModel& row, const QuantisationError& q, double tolerance, int fixed_positions,
                                 int max_positions);

}  // namespace rangesim::golden
