#pragma once
// `rangesim simulate` for ls-conventional: the clock-level model (bare kernels or SystemC) on a
// scene, the range map by triangulation, its error against the scene's exact ground truth and
// the measured frame timing beside golden::frame_timing. Returns data (systemc/common/simulation.h);
// app/simulate/ writes and prints it.
#include "systemc/common/simulation.h"

namespace rangesim::systemc {

// The simulate registry's entry (app/cmd_simulate.h): no aggregated path, no time step.
const SimulateEntry& ls_conventional_simulate_entry();

}  // namespace rangesim::systemc
