#pragma once
// One-dimensional sweeps of the tof-lockin model (thesis 4.1.1 and Fig. 4.4-4.6): accuracy
// against delay, frames averaged, pulse width, signal at several backgrounds, and distance.
// Signal levels quoted by the thesis in volts (light-induced V1 + V2) are converted to the
// photocurrent that gives them (lockin_point.h).
#include <vector>

#include "core/tof_lockin/config.h"
#include "golden/common/sensor_evaluation.h"

namespace rangesim::golden {

// Accuracy at signal `signal_V`, no background, N_p frames, after setting T0 = pulse_width_s
// (0: the preset's) and target distance `distance_m`. NaN where not detectable.
double accuracy_at_voltage_m(const TofLockinConfig& cfg, double signal_V, double distance_m, long long frames,
                             double pulse_width_s = 0);

std::vector<EvalSweep> lockin_sweeps(const TofLockinConfig& cfg, const std::vector<double>& signal_grid_A,
                                     const std::vector<double>& background_grid_A);

}  // namespace rangesim::golden
