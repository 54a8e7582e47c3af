#pragma once
// The physical axes of `evaluate` (--background-lux, --signal-power) and `compare`: a sensor's
// grid in lux of ambient light at the target and watts of source power, turned into its own unit
// by its radiometry (core/radiometry.h, scene/physical.h) under one scene (the default scene's or
// --scene's reflectance, spectrum, filter, beam and camera). The conversion is linear, so a
// log-spaced lux or watt axis is a log-spaced native axis of the same points.
#include <optional>
#include <string>
#include <vector>

#include "core/params.h"
#include "core/radiometry.h"
#include "scene/scene.h"

namespace rangesim::app {

// The scene `compare` and the physical axes of `evaluate` take without --scene (scenes/sunlit-wall.toml
// holds the same text): a 50% Lambertian wall at 1 m in sunlight, a 1 W source at 850 nm behind
// a 10 nm filter.
const char* default_physical_scene_text();
// The scene for one sensor: `path` ("" = the default scene), read for `sensor` (notes kept).
scene::Scene physical_scene(const std::string& path, const std::string& sensor);

struct PhysicalAxes {
  SensorRadiometry radiometry;
  double distance_m = 0;          // where the signal is taken (the scene's target distance)
  double native_per_lux = 0;      // native background per lux
  double native_per_W = 0;        // native signal per watt of source power at distance_m
  std::vector<std::string> notes; // scene notes, and the distance when the preset cannot take it
};

// The axes of `params`' sensor under `scene`. When `set_distance`, the preset's distance key
// (SensorRadiometry::distance_key) is set to the scene's distance if the preset accepts it (else a
// note, and the preset's distance is kept for the accuracy figures).
PhysicalAxes physical_axes(ParamSet& params, const scene::Scene& scene, bool set_distance);

// Applies a physical axis ("LO:HI:N" in lux or W, `flag` for messages) to the preset's grid.
void apply_physical_axis(ParamSet& params, const std::string& axis, const std::string& text, double native_per_unit,
                         const std::string& flag);

}  // namespace rangesim::app
