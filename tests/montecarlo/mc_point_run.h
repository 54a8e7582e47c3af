#pragma once
// One point of a sensor's Monte Carlo run trial by trial and summarised, as `evaluate --trials`
// does (seed 1; `index` picks the point's streams), for the golden-against-MC tests.
#include <cstdint>
#include <vector>

#include "app/montecarlo/mc_stats.h"
#include "systemc/common/montecarlo.h"

namespace rangesim::app::mc {

inline McPointStats run_mc_point(const rangesim::mc::McModel& m, double signal, double background, long long trials,
                                 std::uint64_t index = 0) {
  auto runner = m.point(signal, background, rangesim::mc::point_key(1, index));
  std::vector<double> errors;
  std::vector<char> outlier;  // per detected trial
  for (long long t = 0; t < trials; ++t) {
    const rangesim::mc::McTrial r = runner->trial(t);
    if (r.detected) errors.push_back(r.error), outlier.push_back(r.outlier);
  }
  return summarise_trials(trials, errors, outlier);
}

}  // namespace rangesim::app::mc
