#include "app/montecarlo/mc_evaluate.h"

#include <cmath>
#include <fmt/format.h>
#include <thread>

#include "core/user_error.h"

namespace rangesim::app::mc {

McSweepOptions sweep_options(const EvaluateOptions& opt) {
  McSweepOptions o;
  o.trials = opt.trials.value_or(100);
  if (o.trials < 2 || o.trials > 10000000)
    throw UserError(fmt::format("--trials {}: allowed 2 .. 10000000", o.trials), "trials");
  if (opt.target_error) {
    if (!(std::isfinite(*opt.target_error) && *opt.target_error > 0))
      throw UserError(fmt::format("--target-error {}: allowed a finite error > 0 (metres)", *opt.target_error),
                      "target_error");
    o.target_error_m = *opt.target_error;
  }
  o.max_trials = opt.max_trials.value_or(std::max<long long>(100000, o.trials));
  if (o.max_trials < o.trials || o.max_trials > 1000000000)
    throw UserError(fmt::format("--max-trials {}: allowed --trials ({}) .. 1000000000", o.max_trials, o.trials),
                    "max_trials");
  const int cores = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  o.threads = opt.threads.value_or(cores);
  if (o.threads < 1 || o.threads > 1024)
    throw UserError(fmt::format("--threads {}: allowed 1 .. 1024", o.threads), "threads");
  o.seed = opt.seed.value_or(1);
  if (opt.max_seconds) {
    if (!(std::isfinite(*opt.max_seconds) && *opt.max_seconds > 0))
      throw UserError(fmt::format("--max-seconds {}: allowed a finite time > 0", *opt.max_seconds), "max_seconds");
    o.max_seconds = *opt.max_seconds;
  }
  return o;
}

std::vector<McSweepPoint> detectable_points(const golden::EvalResult& ev) {
  std::vector<McSweepPoint> points;
  for (std::size_t i = 0; i < ev.points.size(); ++i)
    if (ev.points[i].detect == "detectable")
      points.push_back({static_cast<long long>(i), ev.points[i].signal, ev.points[i].background});
  return points;
}

McGrid make_grid(const golden::EvalResult& ev, const std::vector<McSweepPoint>& points, const McSweepResult& r,
                 const McModel& model, const McSweepOptions& o) {
  McGrid grid;
  grid.ev = &ev;
  grid.stats.resize(ev.points.size());
  for (std::size_t k = 0; k < points.size(); ++k) grid.stats[static_cast<std::size_t>(points[k].index)] = r.stats[k];
  grid.unit = model.unit();
  grid.metres_per_unit = model.metres_per_unit();
  grid.trials = o.trials;
  grid.max_trials = o.max_trials;
  grid.target_error_m = o.target_error_m;
  grid.seed = o.seed;
  return grid;
}

}  // namespace rangesim::app::mc
