#pragma once
// ls-demodulation's fixed pattern in the accuracy of golden (docs/model-limits.md): the comparator
// offsets (fixed_pattern.comparator_offset_rms_V), PRNU (prnu_fraction: a gain G = 1 + p z on the
// pixel's beam and background photocurrents) and DSNU (dsnu_rms_A: sigma_d z' added to its dark
// current), each drawn once per pixel and chip.
//
// One frame. Over chips a row's pixels have independent patterns, so in one decision the pattern
// is one more independent term per pixel (decision.h, pixel_decision): the comparator offset adds
// its variance sigma_c^2; PRNU and DSNU move D, whose mean and variance over the draws are taken
// at the 5 x 3 Gauss-Hermite nodes of (z, z') (exact for D up to degree 4 in z and 2 in z': the
// log stage's curvature in the gain is the second-order term a linearisation would miss), and D's
// spread is taken as Gaussian, which is exact where D is linear in the draws. With one decision
// per frame (the preset) the one-frame accuracy is then exact for the comparator offset and to
// that Gaussian shape for PRNU and DSNU.
//
// Averaging. The pattern is the chip's, the same in every frame, so the part of the error it fixes,
// V_fp = Var over chips of E[centre | pattern], does not average. V_fp is linearised in each spot
// pixel's chip offset of D, of rms sigma_j = sqrt(sigma_c^2 + Var_chip D_j) (secants over +- sigma_j
// of the frame's mean centre):
//   V_fp = sum_j sigma_j^2 (d E[centre] / d mu_j)^2,   accuracy^2 = b^2 + V_fp + (V_1 - V_fp) / N_p
// with b and V_1 the one-frame bias and variance; V_fp <= V_1. With several decisions per frame
// the pattern is taken as independent within the frame (an approximation). No closed form exists
// for P(detect) of N_p > 1 frames of one chip (the frames' detections are correlated through it):
// p_detect is NaN there.
#include "core/ls_demodulation/config.h"
#include "golden/ls_demodulation/position.h"

namespace rangesim::golden {

DemodAccuracy accuracy_with_fixed_offsets(const LsDemodulationConfig& cfg, double signal_A, double background_A,
                                          int detections, int frames);

}  // namespace rangesim::golden
