#pragma once
// `rangesim simulate` for ls-demodulation: the clock-level model (bare kernels or SystemC) on a
// light-section scene with a modulated sheet beam over a strong background (scene_optics.h), the
// range map by triangulation, its error against the scene's exact ground truth and the measured
// frame timing beside golden::frame_timing_ls_demodulation. Returns data
// (systemc/common/simulation.h); app/simulate/ writes and prints it.
#include "systemc/common/simulation.h"

namespace rangesim::systemc {

// The simulate registry's entry (app/cmd_simulate.h): aggregated correlation periods
// (--no-aggregate steps them one by one), no time step.
const SimulateEntry& ls_demodulation_simulate_entry();

}  // namespace rangesim::systemc
