#pragma once
// What the optics deliver to the pixel array for one frame access (one sheet-beam position):
// per row, the swings at the end of integration (V = I t / C, thesis eq. 3.1) of the spot peak
// and of the background, and the spot centre on the row. The pixel swing of column i is then
//   v_i(t) = (signal_V g(i - centre_px) + background_V + V_dark) t / T,
// g the Gaussian spot profile of the preset (peak 1), exactly as golden/common/row_model.h has it.
// Plain data, no SystemC: scene/ produces it, systemc/pixel_array consumes it.
#include <cstdint>
#include <functional>
#include <vector>

namespace rangesim::systemc {

struct RowIllumination {
  double signal_V = 0;      // V_sig: spot-peak swing at the end of integration (0: no beam on this row)
  double background_V = 0;  // V_bg: background swing at the end of integration
  double centre_px = 0;     // x0: spot centre, in columns (pixel i is centred at x = i)
};

struct FrameStimulus {
  std::vector<RowIllumination> rows;  // one per sensor row
  // The rows the pixel array simulates (a band of them when rows run on several threads): a source
  // may fill only rows first_row .. first_row + row_count - 1 and leave the others as they are.
  int first_row = 0, row_count = -1;  // -1: every row
};

// Supplies the stimulus of frame access `frame` (0, 1, ...); called once per frame at the pixel
// reset. Must fill exactly `rows` entries (at least the band's).
using StimulusSource = std::function<void(std::uint64_t frame, FrameStimulus& out)>;

}  // namespace rangesim::systemc
