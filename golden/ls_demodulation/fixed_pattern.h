#pragma once
// ls-demodulation's comparator offsets fixed per pixel (fixed_pattern.comparator_offset_rms_V) in
// the accuracy of golden (docs/model-limits.md).
//
// In one decision the offsets of a row's pixels are independent draws, exactly like an offset
// drawn anew at every decision, so pixel_decision adds their variance to the independent noise and
// the one-frame accuracy is exact (one decision per frame, the preset's). Averaging is where they
// differ: the offsets are the chip's, the same in every frame, so the part of the error they fix,
// V_fp = Var over chips of E[centre | offsets], does not average. V_fp is linearised in each spot
// pixel's offset (secants over +- sigma_f of the frame's mean centre):
//   V_fp = sigma_f^2 sum_j (d E[centre] / d mu_j)^2,   accuracy^2 = b^2 + V_fp + (V_1 - V_fp) / N_p
// with b and V_1 the one-frame bias and variance; V_fp <= V_1. With several decisions per frame
// the offsets are taken as independent within the frame (an approximation).
#include "core/ls_demodulation/config.h"
#include "golden/ls_demodulation/position.h"

namespace rangesim::golden {

DemodAccuracy accuracy_with_fixed_offsets(const LsDemodulationConfig& cfg, double signal_A, double background_A,
                                          int detections, int frames);

}  // namespace rangesim::golden
