#pragma once
// Can range be derived at an operating point? (thesis 3.1.2, Fig. 3.3, with a noise check.)
//
// Noise-free criteria as in the thesis, in this order:
//   Saturated            V_sig + V_bg + V_dark > V_sat (eq. 3.3): the pixel still fires, but the
//                        profile is clipped and the accuracy is not controlled;
//   BelowThreshold       the spot peak never reaches theta: A_sf (V_sig + V_bg + V_dark) < theta at t = T;
//   BackgroundActivation background alone reaches theta noise-free (fixed threshold), or, with
//                        noise, the probability that any of the row's pixel.columns background-only
//                        pixels activates during the frame exceeds comparator.false_activation_max;
//   Detectable           otherwise.
#include "core/ls_conventional/config.h"
#include "golden/ls_conventional/evaluation.h"

namespace rangesim::golden {

// P(one background-only pixel activates by t_N), with shot, kTC and read noise.
double pixel_false_activation_probability(const LsConventionalConfig& cfg, double background_V);
// P(any of the row's pixel.columns background-only pixels activates).
double row_false_activation_probability(const LsConventionalConfig& cfg, double background_V);

Detect classify(const LsConventionalConfig& cfg, double signal_V, double background_V);

}  // namespace rangesim::golden
