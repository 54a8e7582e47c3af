#pragma once
// The one renderer of `rangesim simulate`: runs a sensor's scene run (systemc/<sensor>/simulate,
// found in the registry) with the command as its host (trace, output folder, progress), then
// writes range_map.csv, points.csv, frames.csv, range_map.png and summary.json, commits them and
// the trace, and prints the summary (or the JSON with --json). The same for every sensor.
#include "app/cmd_simulate.h"
#include "systemc/common/simulation.h"

namespace rangesim::app {

// What the scene run takes from the command's flags.
systemc::SimulationRequest simulation_request(const SimulateOptions& opt);

// Returns the exit code; nothing is left half-written if the run or a step of the output throws.
int run_and_render(const SimulateOptions& opt, const ParamSet& params, const SimulateEntry& entry);

}  // namespace rangesim::app
