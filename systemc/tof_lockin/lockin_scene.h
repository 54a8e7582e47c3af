#pragma once
// Scene of the tof-lockin clock-level model (scenes/tof-lockin-*.toml;
// docs/tof-lockin-clock.md). SI units in the key names:
//   [scene]   name, description
//   [target]  shape = "plane" | "step"; distance_m (plane, and the far part of
//   the step);
//             step: near_distance_m, step_column_fraction (columns c < fraction
//             x columns are near)
//   [light]   signal_photocurrent_A (pixel photocurrent during the received
//   pulse at
//             reference_distance_m, scaled by (reference / distance)^2),
//             reference_distance_m, background_photocurrent_A (constant, every
//             pixel)
//   [window]  rows, columns (optional: simulate the top-left rows x columns
//   pixels; 0 = whole array)
// Bad input throws rangesim::UserError naming the file, key and allowed range.
#include <string>
#include <vector>

#include "core/tof_lockin_config.h"
#include "systemc/tof_lockin/lockin_kernel.h"

namespace rangesim::systemc::lockin {

struct LockinScene {
  enum class Shape { Plane, Step };
  std::string file;             // where it was loaded from
  std::string name;             // [scene] name
  std::string description;      // [scene] description
  Shape shape = Shape::Plane;   // target shape
  double distance_m = 1.0;      // plane distance; step: far part
  double near_distance_m = 0.5; // step: near part
  double step_column_fraction =
      0.5; // step: columns c < fraction x columns are near
  double signal_photocurrent_A =
      1e-9; // signal photocurrent at reference_distance_m
  double reference_distance_m = 1.0;    // distance of signal_photocurrent_A
  double background_photocurrent_A = 0; // background photocurrent, every pixel
  int rows = 0, columns = 0;            // simulated window (0 = whole array)

  // Window actually simulated for an array of cfg's size.
  int window_rows(const TofLockinConfig &cfg) const {
    return rows > 0 && rows < cfg.pixel.rows ? rows : cfg.pixel.rows;
  }
  int window_columns(const TofLockinConfig &cfg) const {
    return columns > 0 && columns < cfg.pixel.columns ? columns
                                                      : cfg.pixel.columns;
  }
  // Ground-truth distance of pixel (r, c) of an array `columns` wide.
  double distance_at(int r, int c, int array_columns) const;
  // Stimulus of the window, row-major.
  std::vector<LockinPixelStimulus> stimulus(const TofLockinConfig &cfg) const;
};

const char *shape_name(LockinScene::Shape s);
LockinScene load_lockin_scene(const std::string &path);

} // namespace rangesim::systemc::lockin
