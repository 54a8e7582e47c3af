#pragma once
// The preset of `rangesim evaluate` with its flags applied (grid, samplings, ADC bits, frames),
// validated: shared by the closed-form run (cmd_evaluate.cpp) and the Monte Carlo run
// (montecarlo/cmd_evaluate_mc.cpp). Throws UserError naming the flag, key and allowed range.
#include "app/commands.h"
#include "core/params.h"

namespace rangesim::app {

ParamSet evaluate_params(const EvaluateOptions& opt);

}  // namespace rangesim::app
