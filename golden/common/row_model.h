#pragma once
// One row of the sensor at one operating point (V_sig, V_bg), noise-free, in closed form.
//
// Pixel i sits at x_i = i (pixel centres, in px); the spot centre x0 is placed around the middle
// pixel c = columns / 2, away from the row ends. The noise-free swing of pixel i at sampling k
// (t_k = k T / N, k = 1..N) is
//   v_i(t_k) = (V_sig g(x_i - x0) + V_bg + V_dark) k / N,
// and its code reaches m (1 = the comparator fires) when A_sf v_i(t_k) >= theta + (m - 1) LSB.
// Solving that for the distance gives a half-width h_{k,m}: code >= m iff |x_i - x0| <= h_{k,m}.
// Every noise-free result (estimate, breakpoints, exact error integral) follows from these
// half-widths, so no pixel is ever simulated one by one.
#include <vector>

#include "core/ls_conventional/config.h"
#include "golden/common/quantiser.h"

namespace rangesim::golden {

struct RowModel {
  LsConventionalConfig cfg;  // the sensor
  double signal_V = 0;       // V_sig: spot-peak swing at the end of integration
  double background_V = 0;   // V_bg: background swing at the end of integration
  double dark_V = 0;         // V_dark = I_dark T / C
  Quantiser quantiser;       // threshold / codes at this background
  int samplings = 1;         // N
  int columns = 1;           // pixels in the row
  int centre_pixel = 0;      // c: the spot centre is taken in [c - 0.5, c + 0.5]
  // half_width_px[k-1][m-1] = h_{k,m}; +infinity: every pixel of the row (background alone
  // reaches the level); negative: no pixel reaches it. Non-increasing in m and non-decreasing in k.
  std::vector<std::vector<double>> half_width_px;
};

RowModel make_row_model(const LsConventionalConfig& cfg, double signal_V, double background_V);

// Noise-free swing of pixel i at sampling k (1..N) for a spot centred at x0.
double row_pixel_swing_V(const RowModel& row, int pixel, double x0_px, int k);

// Mean photo-electrons (signal + background + dark) integrated by pixel i up to sampling k.
double row_pixel_mean_electrons(const RowModel& row, int pixel, double x0_px, int k);

}  // namespace rangesim::golden
