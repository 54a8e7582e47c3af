#pragma once
// The steps of `evaluate --trials` that return data (the command adds the journal, MPI, the
// files and the messages; the Python module calls the same steps): its options from the flags,
// the grid points it runs, and the grid of statistics its outputs are made from.
#include <vector>

#include "app/commands.h"
#include "app/montecarlo/mc_output.h"
#include "app/montecarlo/mc_sweep.h"
#include "golden/common/sensor_evaluation.h"

namespace rangesim::app::mc {

// --trials, --target-error, --max-trials, --threads, --seed, --max-seconds of `opt`, checked:
// UserError naming the flag and its allowed range.
McSweepOptions sweep_options(const EvaluateOptions& opt);

// The sweep's points: the detectable points of the golden evaluation, keyed by grid index.
std::vector<McSweepPoint> detectable_points(const golden::EvalResult& ev);

// The statistics of a complete sweep laid on the grid (McGrid::ev points to `ev`, which must
// outlive the grid).
McGrid make_grid(const golden::EvalResult& ev, const std::vector<McSweepPoint>& points, const McSweepResult& r,
                 const McModel& model, const McSweepOptions& o);

}  // namespace rangesim::app::mc
