#pragma once
// Test hook for the "abandon stuck trials after the grace time" path of `evaluate --trials`: with
// RANGESIM_TEST_STUCK_POINT=<grid index> in the environment, trial 0 of that grid point never
// returns (it sleeps, using no CPU), standing in for a kernel stuck beyond its own budget, so the
// path can be tested through the binary (tests/montecarlo). Unset, the model is returned as is.
#include <cstdint>
#include <memory>

#include "app/montecarlo/mc_sweep.h"

namespace rangesim::app::mc {

inline constexpr const char* kStuckPointEnv = "RANGESIM_TEST_STUCK_POINT";

// `model`, or a wrapper whose runner for the hooked grid point (keyed by `seed`) never returns.
// Throws UserError if the variable is set but is not a grid index (a non-negative integer).
std::unique_ptr<McModel> with_stuck_point_hook(std::unique_ptr<McModel> model, std::uint64_t seed);

}  // namespace rangesim::app::mc
