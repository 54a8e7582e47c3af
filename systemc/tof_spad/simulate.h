#pragma once
// `rangesim simulate` for tof-spad: the clock-level model (bare kernels or the sc_module) on a
// tof-spad scene (scene_adapter.h), the golden estimator on the measured histograms, the range
// error against the scene's ground truth and the measured frame timing beside
// golden::frame_timing_tof_spad (docs/tof-spad-clock.md). Rows outside the simulated window still
// cost their cycles (the timing is always the whole array's). Returns data
// (systemc/common/simulation.h); app/simulate/ writes and prints it.
#include "systemc/common/simulation.h"

namespace rangesim::systemc {

// The simulate registry's entry (app/cmd_simulate.h): aggregated laser cycles (--no-aggregate
// runs them one by one), no time step.
const SimulateEntry& tof_spad_simulate_entry();

}  // namespace rangesim::systemc
