#include "app/physical_axes.h"

#include <fmt/format.h>

#include "app/cli_common.h"
#include "core/grid_rules.h"
#include "core/sensor_registry.h"
#include "core/user_error.h"
#include "scene/physical.h"

namespace rangesim::app {

const char* default_physical_scene_text() {
  return R"(# The default physical scene of `rangesim compare` and of `evaluate --background-lux/--signal-power`
# (app/physical_axes.cpp holds the same text): a 50% grey wall at 1 m in sunlight, lit by a 1 W
# source at 850 nm; every sensor sees it through a 10 nm band-pass filter. Radiometry: docs/radiometry.md.
[scene]
name = "sunlit-wall"
description = "50% wall at 1.0 m, 10 klux sunlight, 1 W at 850 nm, 10 nm filter"

[target]
shape = "plane"
distance_m = 1.0
reflectance = 0.5

[ambient]
illuminance_lux = 10000.0      # overcast daylight; full sun is about 100 klux
spectrum = "sunlight"

[source]
power_W = 1.0                  # mean optical power
wavelength_m = 850e-9
beam = "sheet"                 # light-section: a sheet; time-of-flight: its scan is a flood

[camera]
filter_bandwidth_m = 10e-9     # narrow-band filter FWHM in front of the lens
)";
}

scene::Scene physical_scene(const std::string& path, const std::string& sensor) {
  if (path.empty()) return scene::load_scene_text(default_physical_scene_text(), "default scene (sunlit-wall)", sensor);
  scene::Scene s = scene::load_scene(path, sensor);
  if (!s.light.present)
    throw UserError(fmt::format("{}: --scene for physical axes needs [ambient] and [source] (the light in lux and "
                                "watts); see scenes/sunlit-wall.toml",
                                path));
  return s;
}

PhysicalAxes physical_axes(ParamSet& params, const scene::Scene& scene, bool set_distance) {
  PhysicalAxes a;
  a.notes = scene.notes;
  a.radiometry = radiometry_for(params, params.origin());
  a.distance_m = scene.distance_m;
  if (set_distance && !a.radiometry.distance_key.empty()) {
    const ParamSet before = params;
    try {
      const ParamSchema& schema = schema_for(params.sensor_id(), params.origin());
      params.set_real(a.radiometry.distance_key, scene.distance_m, "--scene target.distance_m", schema);
      find_sensor(params.sensor_id())->validate(params);
    } catch (const UserError& e) {
      params = before;
      a.notes.push_back(fmt::format("{}: the scene's distance {:g} m is not a {} evaluation distance ({}); its "
                                    "accuracy is taken at the preset's {} = {:g} m",
                                    scene.file, scene.distance_m, params.sensor_id(), e.what(),
                                    a.radiometry.distance_key, params.real(a.radiometry.distance_key)));
    }
  }
  std::vector<std::string> light_notes;
  (void)scene::native_light(scene, a.radiometry, &light_notes);
  a.notes.insert(a.notes.end(), light_notes.begin(), light_notes.end());
  a.native_per_lux = scene::native_background_per_lux(scene, a.radiometry);
  a.native_per_W = scene::native_signal_per_W(scene, a.radiometry, a.distance_m);
  return a;
}

void apply_physical_axis(ParamSet& params, const std::string& axis, const std::string& text, double native_per_unit,
                         const std::string& flag) {
  const GridAxis g = parse_grid_axis(text, flag);
  const ParamSchema& schema = schema_for(params.sensor_id(), params.origin());
  std::string lo_key, hi_key;
  for (const auto& p : schema.params) {
    if (p.key.rfind("evaluation." + axis + "_min_", 0) == 0) lo_key = p.key;
    if (p.key.rfind("evaluation." + axis + "_max_", 0) == 0) hi_key = p.key;
  }
  if (lo_key.empty() || hi_key.empty())
    throw UserError(fmt::format("{}: sensor {} has no evaluation grid", flag, params.sensor_id()), flag.substr(2));
  if (!(native_per_unit > 0))
    throw UserError(fmt::format("{}: {} sees none of this light under the scene (its radiometry gives 0 {} per unit; "
                                "e.g. an LED spectrum has no near-infrared)",
                                flag, params.sensor_id(), axis),
                    flag.substr(2));
  if (!(g.lo > 0))
    throw UserError(fmt::format("{} {}: LO must be > 0 (a log-spaced axis)", flag, text), flag.substr(2));
  params.set_real(lo_key, g.lo * native_per_unit, flag, schema);
  params.set_real(hi_key, g.hi * native_per_unit, flag, schema);
  params.set_integer("evaluation." + axis + "_points", g.n, flag, schema);
}

}  // namespace rangesim::app
