#pragma once
// The preset of `rangesim evaluate` with its flags applied (grid, samplings, ADC bits, frames),
// validated: shared by the closed-form run (cmd_evaluate.cpp) and the Monte Carlo run
// (montecarlo/cmd_evaluate_mc.cpp). Throws UserError naming the flag, key and allowed range.
#include "app/commands.h"
#include "app/resource_estimate.h"
#include "core/params.h"

namespace rangesim::app {

ParamSet evaluate_params(const EvaluateOptions& opt);

// The grid and model flags of `evaluate` (--samplings, --adc-bits, --frames, --signal,
// --background; the rest of `opt` is not read) applied to a loaded preset, with the same checks.
void apply_evaluate_flags(ParamSet& params, const EvaluateOptions& opt);

// What `evaluate` over the preset's grid needs (app/resource_estimate.h): streamed, a block of rows
// and the heat maps' cells in memory; with Monte Carlo, every point and its statistics.
ResourceEstimate evaluate_estimate(const ParamSet& params, bool monte_carlo);

}  // namespace rangesim::app
