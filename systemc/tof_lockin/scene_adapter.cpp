#include "systemc/tof_lockin/scene_adapter.h"

#include <fmt/format.h>
#include <stdexcept>

#include "core/user_error.h"
#include "scene/physical.h"

namespace rangesim::scene {

systemc::lockin::LockinScene to_lockin_scene(const Scene& scene_in, const TofLockinConfig& cfg,
                                             const SensorRadiometry* radiometry) {
  using systemc::lockin::LockinScene;
  const auto need_radiometry = [&]() -> const SensorRadiometry& {
    if (!radiometry) throw std::logic_error("to_lockin_scene: a physical scene needs the sensor's radiometry");
    return *radiometry;
  };
  const bool native_step = scene_in.shape != TargetShape::Step ||
                           (!scene_in.has("target.step_y_m") && !scene_in.has("target.step_distance_m"));
  const bool rasterise =
      scene_in.shape == TargetShape::Tilted || scene_in.shape == TargetShape::Objects || !native_step;
  const Scene s = rasterise ? rasterised(scene_in, need_radiometry()) : scene_in;
  LockinScene l;
  l.notes = s.notes;
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
  const bool own_light = s.has("light.signal_photocurrent_A") && s.has("light.background_photocurrent_A");
  if (s.light.present && own_light) {
    l.notes.push_back(fmt::format("{}: [light] overrides [ambient] / [source] for tof-lockin", s.file));
  } else if (s.light.present) {
    const NativeLight n = native_light(s, need_radiometry(), &l.notes);
    if (!s.has("light.signal_photocurrent_A")) {
      l.reference_distance_m = s.distance_m;
      l.signal_photocurrent_A = n.signal_at(s.distance_m);
    }
    if (!s.has("light.background_photocurrent_A")) l.background_photocurrent_A = n.background;
    if (s.light.beam == BeamShape::Spot)
      l.notes.push_back(
          fmt::format("{}: source.beam = \"spot\": tof-lockin's scene lights every pixel; each gets the "
                      "spot's irradiance",
                      s.file));
  }
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
