#pragma once
// One-dimensional sweeps (thesis Fig. 3.6, 3.8, 3.9; selectivity; step settling) and the
// published figures of ls-demodulation with rangesim's values.
#include <vector>

#include "core/ls_demodulation/config.h"
#include "golden/common/published_figure.h"
#include "golden/common/sensor_evaluation.h"

namespace rangesim::golden {

std::vector<EvalSweep> demod_sweeps(const LsDemodulationConfig& cfg);
std::vector<PublishedFigure> demod_published_figures(const LsDemodulationConfig& cfg);

// Signal of the nominal ("effective area") accuracy point: 0.1 x the grid top.
double demod_nominal_signal_A(const LsDemodulationConfig& cfg);

}  // namespace rangesim::golden
