#pragma once
// The one renderer of `rangesim simulate`: runs a sensor's scene run (systemc/<sensor>/simulate,
// found in the registry) with the command as its host (trace, output folder, progress), then
// writes range_map.{csv,npy}, points.{csv,npy}, frames.csv, range_map.png and summary.json, commits
// them and the trace, and prints the summary (or the JSON with --json). The same for every sensor.
#include <cstddef>

#include "app/cmd_simulate.h"
#include "systemc/common/simulation.h"

namespace rangesim::app {

// Tables of more than this many numbers are written as .npy unless --csv (a full ls-conventional
// map: 137k range values, 1.5M in points): formatting text for them would cost as much as the
// simulation. Smaller ones stay CSV, easy to read by eye.
constexpr std::size_t kNpyMinValues = 100000;

// What the scene run takes from the command's flags.
systemc::SimulationRequest simulation_request(const SimulateOptions& opt);

// Returns the exit code; nothing is left half-written if the run or a step of the output throws.
int run_and_render(const SimulateOptions& opt, const ParamSet& params, const SimulateEntry& entry);

}  // namespace rangesim::app
