#pragma once
// Frame timing of ls-conventional from its clock schedule.
//
// One frame access (one sheet-beam position) is: pixel reset, then N samplings each made of a
// comparator latch, the chained-search settle and the bit-serial stream of the activated run's
// column addresses (left and right edge), then the output of the centres from the row-parallel
// processors. Rows run in parallel, so the row count does not enter.
//   cycles = reset + N (latch + search + addresses_per_sampling * address_bits) + output
// A range map is `beam_positions` frame accesses.
#include <string>
#include <vector>

#include "core/ls_conventional_config.h"

namespace rangesim::golden {

struct TimingPhase {
  std::string name;     // "reset", "latch", "search", "address_stream", "output"
  long long cycles;     // clock cycles per frame access spent in this phase
  double time_s;        // cycles / clock
};

// Also the frame timing of the other sensors (golden/<sensor>/frame_timing.h): there a "frame"
// is one sensor frame (accumulation + readout) and a "range map" the frames that make one
// range image (e.g. signal + ambient frame).
struct FrameTiming {
  std::vector<TimingPhase> phases;  // in schedule order, summed over samplings
  long long frame_cycles = 0;       // cycles of one frame access
  double frame_time_s = 0;          // one frame access
  double frame_access_rate_Hz = 0;  // 1 / frame_time_s
  double range_map_time_s = 0;      // beam_positions frame accesses
  double range_maps_per_s = 0;
  int samplings = 0;
  double clock_Hz = 0;              // clock the cycles count
  long long frames_per_range_map = 0;  // ls-conventional: beam positions
};

FrameTiming frame_timing(const FrameTimingConfig& timing, int samplings);

}  // namespace rangesim::golden
