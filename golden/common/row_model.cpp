#include "golden/common/row_model.h"

#include <limits>

#include "golden/common/pixel.h"
#include "golden/common/spot.h"

namespace rangesim::golden {

RowModel make_row_model(const LsConventionalConfig& cfg, double signal_V, double background_V) {
  RowModel r;
  r.cfg = cfg;
  r.signal_V = signal_V;
  r.background_V = background_V;
  r.dark_V = dark_voltage_V(cfg.pixel);
  r.quantiser = make_quantiser(cfg, background_V);
  r.samplings = cfg.multisampling.samplings;
  r.columns = cfg.pixel.columns;
  r.centre_pixel = cfg.pixel.columns / 2;
  const double A = cfg.pixel.source_follower_gain;
  const double inf = std::numeric_limits<double>::infinity();
  r.half_width_px.assign(r.samplings, std::vector<double>(r.quantiser.max_code));
  for (int k = 1; k <= r.samplings; ++k)
    for (int m = 1; m <= r.quantiser.max_code; ++m) {
      // A (V_sig g + V_bg + V_dark) k / N >= theta_m  <=>  g >= level.
      const double swing_needed_V = code_threshold_V(r.quantiser, m) / A * r.samplings / k;
      const double rest_V = swing_needed_V - background_V - r.dark_V;
      double h;
      if (rest_V <= 0)
        h = inf;  // the background alone reaches the level: every pixel of the row
      else if (signal_V <= 0)
        h = -1;
      else
        h = spot_half_width_px(r.cfg.spot, rest_V / signal_V);
      r.half_width_px[k - 1][m - 1] = h;
    }
  return r;
}

double row_pixel_swing_V(const RowModel& row, int pixel, double x0_px, int k) {
  const double g = spot_profile(row.cfg.spot, pixel - x0_px);
  return pixel_swing_V(row.signal_V, g, row.background_V, row.dark_V, static_cast<double>(k) / row.samplings);
}

double row_pixel_mean_electrons(const RowModel& row, int pixel, double x0_px, int k) {
  return row_pixel_swing_V(row, pixel, x0_px, k) * electrons_per_volt(row.cfg.pixel);
}

}  // namespace rangesim::golden
