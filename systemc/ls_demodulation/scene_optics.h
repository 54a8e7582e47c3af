#pragma once
// ls-demodulation's scene adapter (beside the sensor; scene/ is only the reader): a light-section
// scene as the demodulating sensor sees it (docs/ls-demodulation-clock.md, "Scenes") and its
// triangulation, i.e. the per-frame stimulus and the exact ground truth of every (frame, row).
#include <cstdint>
#include <string>
#include <vector>

#include "core/ls_demodulation/config.h"
#include "systemc/ls_demodulation/sensor_kernel.h"

namespace rangesim::scene {

// A light-section scene for ls-demodulation: a plane (optionally tilted row by row), a sheet beam
// stepping across the columns, a beam-on photocurrent at the spot peak and a uniform background.
struct DemodScene {
  std::string file;                 // path as given
  std::string name;                 // [scene].name
  std::string description;          // [scene].description
  double distance_m = 1.0;          // [target].distance_m: range of row 0
  double tilt_m_per_row = 0.0;      // [target].tilt_m_per_row: range change per row
  double signal_A = 1.11e-10;       // [beam].signal_A: beam-on photocurrent at the spot peak
  double first_column_px = 5.0;     // [beam].first_column_px: spot column of frame 0 at the preset's optics.distance_m
  double columns_per_frame = 1.0;   // [beam].columns_per_frame: beam step per frame, in pixels
  double background_A = 1e-7;       // [background].photocurrent_A: per pixel
  std::string shape = "plane";      // "plane" (tilted row by row) or "depth_map"
  std::vector<double> depth_map_m;  // depth_map: depth of every pixel, row-major
  int map_columns = 0;              // depth_map: array columns
  std::vector<std::string> notes;   // scene keys this sensor does not use (scene/physical.h)
};

// Reads `path` with the scene reader (sensor "ls-demodulation") and checks it against the preset;
// throws UserError naming the file and key.
// A physical scene ([ambient], [source]) is turned into photocurrents by the sensor's radiometry
// (`params`, core/ls_demodulation/radiometry.cpp); a shape other than a plane or a depth map is
// rasterised into a depth map.
DemodScene load_demod_scene(const std::string& path, const LsDemodulationConfig& cfg, const ParamSet& params);

// Triangulation of the light-section geometry (thesis eq. 1.1): a target at range z images the
// sheet beam at disparity d(z) = f B / (p z) pixels; beam position b is aimed so that a target at
// the preset's optics.distance_m images at column x_b = first + b step.
struct DemodOptics {
  const LsDemodulationConfig& cfg;
  const DemodScene& sc;
  double disparity_px(double z) const {
    return cfg.optics.focal_length_m * cfg.optics.baseline_m / (cfg.pixel.pitch_m * z);
  }
  double beam_column(long long b) const { return sc.first_column_px + sc.columns_per_frame * static_cast<double>(b); }
  // Depth of the lit point on a row. Plane: the row's depth. Depth map: the first column (from
  // the left) where the stripe of the pixel's own depth lands on that pixel (scene/depth_map.h,
  // the root finder ls-conventional uses too); -1 when the beam misses the map on this row.
  double range_m(long long b, int row) const;
  // Exact stripe centre on a row (NaN: the beam misses), and whether it lies on the array.
  double centre_px(long long b, int row) const;
  bool visible(long long b, int row) const;
  // Depth from an estimated stripe column (NaN behind the beam).
  double range_from_centre_m(long long b, double x) const;
  // The pixel currents of frame f: the Gaussian spot on every lit row over the background.
  void stimulus(std::uint64_t f, systemc::DemodStimulus& s) const;
};
}  // namespace rangesim::scene
