#include "systemc/tof_lockin/scene_adapter.h"

#include <fmt/format.h>

#include "core/user_error.h"

namespace rangesim::scene {

systemc::lockin::LockinScene to_lockin_scene(const Scene& s, const TofLockinConfig& cfg) {
  using systemc::lockin::LockinScene;
  LockinScene l;
  l.file = s.file;
  l.name = s.name;
  l.description = s.description;
  l.shape = s.shape == TargetShape::Step       ? LockinScene::Shape::Step
            : s.shape == TargetShape::DepthMap ? LockinScene::Shape::DepthMap
                                               : LockinScene::Shape::Plane;
  l.distance_m = s.distance_m;
  l.near_distance_m = s.get("target.near_distance_m", l.near_distance_m);
  l.step_column_fraction = s.get("target.step_column_fraction", 0.5);
  l.signal_photocurrent_A = s.get("light.signal_photocurrent_A", 0);
  l.reference_distance_m = s.get("light.reference_distance_m", 1.0);
  l.background_photocurrent_A = s.get("light.background_photocurrent_A", 0);
  // The window is never clamped to the array: a scene asking for more than the preset's pixels is
  // refused, as tof-spad's is.
  const auto window = [&](const char* key, int array) {
    const double v = s.get(key, 0);
    if (v > array)
      throw UserError(fmt::format("{}: {} = {:g}: allowed 0 (the whole array) or 1 <= value <= {} (the preset's {})",
                                  s.file, key, v, array,
                                  std::string(key) == "window.rows" ? "pixel.rows" : "pixel.columns"));
    return static_cast<int>(v);
  };
  l.rows = window("window.rows", cfg.pixel.rows);
  l.columns = window("window.columns", cfg.pixel.columns);
  for (const char* k : {"target.distance_m", "target.near_distance_m"})
    if (s.get(k, 1) > 1000)
      throw UserError(
          fmt::format("{}: {} = {:g} is out of range for tof-lockin; allowed: (0, 1000] m", s.file, k, s.get(k, 1)));
  if (s.shape == TargetShape::DepthMap) {
    l.map_columns = cfg.pixel.columns;
    l.depth_map_m = s.depth_map->resample(cfg.pixel.rows, cfg.pixel.columns);
    for (double z : l.depth_map_m)
      if (z > 1000)
        throw UserError(fmt::format(
            "{}: target.depth_map_file: distance {:g} m is out of range for tof-lockin; allowed: (0, 1000] m", s.file,
            z));
  }
  return l;
}

}  // namespace rangesim::scene
