#pragma once
// The Monte Carlo sweep over grid points: points handed out to worker threads from a shared
// counter, every point's trials run in trial order by one worker, the point's statistics
// appended to the sweep journal as soon as they are final. Results are stored by point index, so
// neither the thread count nor the order in which points are visited can change them.
//
// Trials per point: `trials`; with a target error E (metres), more are added until the 95% CI
// half-width of the accuracy is at most E: the next count is the larger of n + trials and the
// count the current half-width projects (hw ~ 1/sqrt(n)) x 1.2, never above `max_trials`.
#include <atomic>
#include <cstdint>
#include <optional>
#include <vector>

#include "app/montecarlo/mc_stats.h"
#include "app/sweep_journal.h"
#include "systemc/common/montecarlo.h"

namespace rangesim::app::mc {

// The trial models are the sensors' own (systemc/<sensor>/montecarlo.h); the sweep only runs them.
using rangesim::mc::McModel;
using rangesim::mc::McPointRunner;
using rangesim::mc::McTrial;
using rangesim::mc::point_key;

struct McSweepPoint {
  long long index = 0;  // grid index (row-major, as EvalResult::points): keys the random streams
  double signal = 0, background = 0;
};

struct McSweepOptions {
  long long trials = 100;         // first batch per point
  double target_error_m = 0;      // 0: no target
  long long max_trials = 100000;  // cap per point (trial budget)
  int threads = 1;
  std::uint64_t seed = 1;
  double max_seconds = 0;                   // wall-time budget, 0: none; when exceeded the sweep stops like on Ctrl-C
  const std::atomic<bool>* stop = nullptr;  // set asynchronously (SIGINT): finish nothing new
  std::vector<std::size_t> order;           // visiting order of `points` (empty: as given); tests shuffle it
  // Progress callback from the calling thread about every `progress_interval_s`:
  // (points done, points total, trials run, seconds elapsed, seconds left estimated).
  void (*progress)(long long, long long, long long, double, double) = nullptr;
  double progress_interval_s = 1.0;
  double stop_grace_s = 10.0;  // after a stop, how long running trials may take to return
};

struct McSweepResult {
  std::vector<std::optional<McPointStats>> stats;  // per entry of `points`
  std::vector<long long> point_variates;           // per entry: variates drawn in this process (-1: unknown)
  bool complete = false;                           // every point has its statistics
  bool stopped = false;                            // stop flag seen
  bool out_of_time = false;                        // max_seconds exceeded
  bool abandoned = false;                          // workers did not return within stop_grace_s of a stop: the
                                                   // caller must end the process now (std::_Exit); journal is safe
  std::vector<std::size_t> stuck_points;           // abandoned: entries of `points` whose trials were still running
  long long trials_run = 0;                        // trials run in this process (not from the journal)
  long long variates = 0;                          // random variates drawn in this process (-1: not counted)
  long long points_from_journal = 0;
  long long points_capped = 0;  // target error not reached within max_trials
  double worst_capped_half_width_m = 0;
  double wall_s = 0;
};

// Runs the sweep. With a journal, points already in it are taken from it (not rerun) and every
// newly finished point is appended. Exceptions in a worker (kernel budget exceeded, ...) stop the
// sweep and are rethrown here.
McSweepResult run_mc_sweep(const McModel& model, const std::vector<McSweepPoint>& points, const McSweepOptions& opt,
                           SweepJournal* journal);

// Whether a point's statistics meet the target (always true without one).
bool meets_target(const McPointStats& s, double metres_per_unit, double target_error_m);

}  // namespace rangesim::app::mc
