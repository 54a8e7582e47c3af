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

// The chip's fixed pattern (core/nonideal.h) as the pixel array takes it, per pixel of the array
// (row-major, rows x columns; an empty vector: that term is off). Fixed per chip: the scene
// adapter makes it once (systemc/ls_conventional/nonideal_pattern.h) and every frame points at it.
struct PixelPattern {
  std::vector<double> gain;          // PRNU: relative gain of the pixel's photo swing (signal and background)
  std::vector<double> dark_V;        // DSNU: the pixel's dark swing at the end of integration (replaces V_dark)
  std::vector<double> offset_V;      // comparator offset at its input (fires when A_sf v + offset >= theta)
  std::vector<double> max_offset_V;  // per row: the largest offset (bounds the row's sparse window)
  bool empty() const { return gain.empty() && dark_V.empty() && offset_V.empty(); }
};

struct FrameStimulus {
  std::vector<RowIllumination> rows;  // one per sensor row
  // Point spread and crosstalk (core/nonideal.h BlurConfig): each pixel's spot swing at the end of
  // integration (row-major, rows x columns), replacing signal_V g(i - centre_px); the background
  // stays the row's (a uniform background stays uniform under the spread). Empty: no spread.
  std::vector<double> signal_px_V;
  const PixelPattern* pattern = nullptr;  // the chip's fixed pattern (null or empty: none)
  // Whether the pixel array must take each pixel's own drive (the per-pixel path).
  bool per_pixel() const { return !signal_px_V.empty() || (pattern != nullptr && !pattern->empty()); }
  // The rows the pixel array simulates (a band of them when rows run on several threads): a source
  // may fill only rows first_row .. first_row + row_count - 1 and leave the others as they are.
  int first_row = 0, row_count = -1;  // -1: every row
};

// Supplies the stimulus of frame access `frame` (0, 1, ...); called once per frame at the pixel
// reset. Must fill exactly `rows` entries (at least the band's).
using StimulusSource = std::function<void(std::uint64_t frame, FrameStimulus& out)>;

}  // namespace rangesim::systemc
