#pragma once
// `rangesim simulate` for tof-lockin: the clock-level model of the pulsed lock-in ToF sensor
// (bare kernels or SystemC) on a tof-lockin scene (scene_adapter.h); range map by eq. 2.25, its
// error against the scene's ground truth and the golden expectation, frame timing measured from
// simulated time beside golden::frame_timing_tof_lockin (docs/tof-lockin-clock.md). Returns data
// (systemc/common/simulation.h); app/simulate/ writes and prints it.
#include "systemc/common/simulation.h"

namespace rangesim::systemc {

// The simulate registry's entry (app/cmd_simulate.h): aggregated accumulation periods
// (--no-aggregate steps them one by one) and a continuous-time overlap --time-step coarsens.
const SimulateEntry& tof_lockin_simulate_entry();

}  // namespace rangesim::systemc
