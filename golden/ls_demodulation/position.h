#pragma once
// Position estimate of the spot across a row from the comparator decisions, and its accuracy.
//
// Each pixel i at x_i sees the Gaussian spot (golden/common/spot.h) with beam-on current I_sig g(x_i - x0)
// and decides active with probability p_i (decision.h). The row readout reports the centre of the
// activated run, (left + right) / 2 (the light-section readout shared with ls-conventional); no
// active pixel is an explicit "no detection". Given the frame-common offset o the pixels are
// independent, so the exact mean m(o) and variance v(o) of one decision's estimate come from
// golden::edge_centre_moments (one sampling). A frame averages the centres of its K decisions:
// given o, variance v(o) / K_eff with K_eff = E[detections | at least one] (exact when every
// decision detects); over o (Gauss-Hermite) the frame estimate has bias b = E[m] - x0 and
// variance Var_o[m] + E_o[v / K_eff]. N_p frames average independently: the error is
// b^2 + Var / N_p. accuracy = sqrt(mean over x0 of that), x0 on a midpoint grid across one pixel,
// each position weighted by the probability that the N_p frames detect at all (the rms error
// given a detection, as the Monte Carlo measures it with the spot uniform across the pixel).
// Where background pixels may activate, the trials with an outlier (an activation outside the
// spot's pixels, golden/common/spot.h) are split off: given none, the spot's pixels are as if
// alone (independent given o), so the clean accuracy comes from their moments, weighted by
// P(no outlier | o). Exact for K = N_p = 1 (the preset); the 16-position midpoint rule is
// converged to 0.13 % on the preset's grid (measured against 256 positions).
#include "core/ls_demodulation/config.h"

namespace rangesim::golden {

struct DemodAccuracy {
  double accuracy_px = 0;        // rms error over spot positions (bias and noise)
  double bias_rms_px = 0;        // rms over positions of the bias (what averaging cannot remove)
  double noise_std_px = 0;       // rms over positions of the frame estimate's std before N_p averaging
  double worst_error_px = 0;     // largest |bias| + 3 std over positions (a "maximum error")
  double p_detect_min = 0;       // smallest P(one decision detects) over positions
  double p_detect = 0;           // mean over positions of P(some frame of N_p detects); NaN: no closed form
  double detected_fraction = 0;  // fraction of positions with P(detect) > 1e-9 (others left out)
  double accuracy_m = 0;         // accuracy_px through triangulation at optics.distance_m
  // Outliers (golden/common/spot.h): an activation outside the spot's pixels in some decision.
  double p_outlier = 0;          // mean over positions of P(an outlier in the N_p frames); NaN: no closed form
  double accuracy_clean_px = 0;  // rms error of the detecting trials without an outlier; NaN: no closed form
  double accuracy_clean_m = 0;
};

DemodAccuracy position_accuracy(const LsDemodulationConfig& cfg, double signal_A, double background_A, int detections,
                                int frames_averaged);

// Range change per pixel at optics.distance_m (golden/common/triangulation.h).
double demod_range_per_px_m(const LsDemodulationConfig& cfg);

}  // namespace rangesim::golden
