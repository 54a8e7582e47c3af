#pragma once
// tof-spad's scene adapter (beside the sensor; scene/ is only the reader): a tof-spad scene
// (scenes/tof-spad-*.toml) checked against the preset, as the SPAD pixels see it: the depth, the
// signal and background count rates of every pixel, the beam's footprint and the simulated
// window. Default window (speed): 4 rows x 16 columns around the array centre, i.e. 4 TDC groups
// per row; --dense simulates every pixel.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "core/physics.h"
#include "core/radiometry.h"
#include "core/tof_spad/config.h"
#include "systemc/tof_spad/sensor_kernel.h"

namespace rangesim::scene {

// A tof-spad scene: a plane or a step (two planes split at a column), SI units.
struct SpadScene {
  std::string file, name, description, shape;  // shape: "plane" or "step"
  double distance_m = 2.0;                     // plane distance (step: columns < step_column)
  double step_distance_m = 3.0;                // step: columns >= step_column
  int step_column = 64;
  double signal_Hz = 1e5;             // PDE-weighted signal count rate per pixel at reference_distance_m
  double reference_distance_m = 2.0;  // signal falls as (reference / distance)^2
  double background_Hz = 1e5;         // ambient count rate per pixel
  int first_row = 62, rows = 4, first_column = 56, columns = 16;                   // default simulated window
  int beam_first_row = 0, beam_rows = 0, beam_first_column = 0, beam_columns = 0;  // lit pixels (the echo's footprint)

  std::vector<double> depth_map_m;  // depth_map: depth of every pixel of the array, row-major
  int map_columns = 0;              // depth_map: array columns
  std::vector<std::string> notes;   // scene keys this sensor does not use (scene/physical.h)
  // Targets beyond the unambiguous range (another sensor's scene): their echo arrives in a later
  // laser period and is seen aliased, at its time modulo the period (kept inside the TDC's
  // usable range [tof_min_s, tof_max_s]); 0 = no target is that far.
  double alias_period_s = 0, tof_min_s = 0, tof_max_s = 0;

  double distance_at(int row, int column) const {
    if (shape == "depth_map") return depth_map_m[static_cast<std::size_t>(row) * map_columns + column];
    return shape == "step" && column >= step_column ? step_distance_m : distance_m;
  }
  bool lit(int row, int column) const {
    return row >= beam_first_row && row < beam_first_row + beam_rows && column >= beam_first_column &&
           column < beam_first_column + beam_columns;
  }
  // Outside the beam's footprint a pixel receives background only (signal 0).
  systemc::spad::PixelRates rates(int row, int column) const {
    const double d = distance_at(row, column);
    const double r = reference_distance_m / d;
    double tof = 2 * d / phys::kSpeedOfLight_m_per_s;
    if (alias_period_s > 0 && tof > tof_max_s)
      tof = std::min(std::max(std::fmod(tof, alias_period_s), tof_min_s), tof_max_s);
    return {lit(row, column) ? signal_Hz * r * r : 0.0, background_Hz, tof};
  }
};

// Reads `path` with the scene reader (sensor "tof-spad") and checks it against the preset and the
// array size: echo inside the TDC range and the laser period, window on TDC group edges. Throws
// UserError naming the file and key.
// A physical scene ([ambient], [source]) is turned into count rates with `radiometry`
// (core/tof_spad/radiometry.cpp) unless the file sets the sensor's own [rates]; a tilted plane or a
// step with a row edge or a column fraction is rasterised into a depth map. `radiometry` may be
// null for a scene that needs neither.
SpadScene load_spad_scene(const std::string& path, const TofSpadConfig& cfg, int array_rows, int array_columns,
                          const SensorRadiometry* radiometry = nullptr);

}  // namespace rangesim::scene
