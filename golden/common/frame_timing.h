#pragma once
// Frame timing from a sensor's clock schedule (`rangesim frame-rate`), by phase: each sensor's
// schedule is in golden/<sensor>/frame_timing.cpp; the clock-level model must measure the same
// cycles.
#include <string>
#include <vector>

namespace rangesim::golden {

struct TimingPhase {
  std::string name;  // "reset", "latch", "search", "address_stream", "output"
  long long cycles;  // clock cycles per frame access spent in this phase
  double time_s;     // cycles / clock
};

// For the light-section sensors a "frame" is one frame access (one sheet-beam position) and a
// range map `beam_positions` of them; for the time-of-flight sensors a frame is one sensor frame
// (accumulation + readout) and a range map the frames that make one range image.
struct FrameTiming {
  std::vector<TimingPhase> phases;  // in schedule order, summed over samplings
  long long frame_cycles = 0;       // cycles of one frame access
  double frame_time_s = 0;          // one frame access
  double frame_access_rate_Hz = 0;  // 1 / frame_time_s
  double range_map_time_s = 0;      // beam_positions frame accesses
  double range_maps_per_s = 0;
  int samplings = 0;
  double clock_Hz = 0;  // clock the cycles count
  long long frames_per_range_map = 0;
};

}  // namespace rangesim::golden
