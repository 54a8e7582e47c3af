#pragma once
// Operating points, detectable ranges and frame rate of ls-demodulation (the pieces that
// evaluate.cpp assembles into an EvalResult; exposed for the tests).
#include <vector>

#include "core/ls_demodulation/config.h"
#include "golden/ls_demodulation/decision.h"
#include "golden/ls_demodulation/position.h"
#include "golden/common/sensor_evaluation.h"

namespace rangesim::golden {

struct DemodPoint {
  double signal_A = 0, background_A = 0;
  DemodDetect detect = DemodDetect::BelowThreshold;
  double sbr_total_dB = 0;         // 20 log10((I_sig + I_bg) / I_bg), eq. 3.11 style
  double sbr_ratio_dB = 0;         // 20 log10(I_sig / I_bg), eq. 3.23 style
  double peak_output_V = 0;        // noise-free D at the spot peak
  double background_output_V = 0;  // noise-free D of a background-only pixel
  double row_false_activation = 0;
  DemodAccuracy accuracy;  // valid when detectable
};

// One operating point; accuracy with the preset's detections and frames (or the given ones).
DemodPoint evaluate_demod_point(const LsDemodulationConfig& cfg, double signal_A, double background_A);
DemodPoint evaluate_demod_point(const LsDemodulationConfig& cfg, double signal_A, double background_A, int detections,
                                int frames);

bool demod_detectable(const LsDemodulationConfig& cfg, double signal_A, double background_A);

// Detectable interval of one axis at a fixed value of the other, edges by bisection in log
// current (60 steps) from the grid points next to them; `axis` holds the grid values.
EvalRange demod_signal_range(const LsDemodulationConfig& cfg, double background_A, const std::vector<double>& axis);
EvalRange demod_background_range(const LsDemodulationConfig& cfg, double signal_A, const std::vector<double>& axis);

// Weakest detectable signal at a background (bisection over [lo, hi]); NaN if none.
double min_detectable_signal_A(const LsDemodulationConfig& cfg, double background_A, double lo_A, double hi_A);

// Frame time: K decisions of one integration window each, then rows x row_cycles of readout.
double demod_frame_time_s(const LsDemodulationConfig& cfg, int detections);

}  // namespace rangesim::golden
