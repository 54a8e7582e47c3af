#pragma once
// Scene of the tof-lockin clock-level model, as the pixels see it: the target depth per pixel
// and the light (docs/tof-lockin-clock.md). Read from a scene file by scene::load_scene and
// scene::to_lockin_scene (systemc/tof_lockin/scene_adapter.h); this struct only turns it into stimulus.
#include <string>
#include <vector>

#include "core/tof_lockin/config.h"
#include "systemc/tof_lockin/sensor_kernel.h"

namespace rangesim::systemc::lockin {

struct LockinScene {
  enum class Shape { Plane, Step, DepthMap };
  std::string file;                      // where it was loaded from
  std::string name;                      // [scene] name
  std::string description;               // [scene] description
  Shape shape = Shape::Plane;            // target shape
  double distance_m = 1.0;               // plane distance; step: far part
  double near_distance_m = 0.5;          // step: near part
  double step_column_fraction = 0.5;     // step: columns c < fraction x columns are near
  double signal_photocurrent_A = 1e-9;   // signal photocurrent at reference_distance_m
  double reference_distance_m = 1.0;     // distance of signal_photocurrent_A
  double background_photocurrent_A = 0;  // background photocurrent, every pixel
  int rows = 0, columns = 0;             // simulated window (0 = whole array)
  std::vector<double> depth_map_m;       // depth map: depth of every pixel of the whole array, row-major
  int map_columns = 0;                   // depth map: columns of the array it was resampled to
  std::vector<std::string> notes;        // scene keys this sensor does not use (scene/physical.h)

  // Window actually simulated for an array of cfg's size.
  int window_rows(const TofLockinConfig& cfg) const {
    return rows > 0 && rows < cfg.pixel.rows ? rows : cfg.pixel.rows;
  }
  int window_columns(const TofLockinConfig& cfg) const {
    return columns > 0 && columns < cfg.pixel.columns ? columns : cfg.pixel.columns;
  }
  // Ground-truth distance of pixel (r, c) of an array `columns` wide.
  double distance_at(int r, int c, int array_columns) const;
  // Stimulus of the window, row-major.
  std::vector<LockinPixelStimulus> stimulus(const TofLockinConfig& cfg) const;
};

const char* shape_name(LockinScene::Shape s);

}  // namespace rangesim::systemc::lockin
