// libFuzzer target: the scene reader and the depth-map image parser on arbitrary bytes. The first
// byte picks the input kind: 0-3 a scene for one of the four shipped sensors (load_scene_text, in
// registry order), 4 a depth-map image (parse_depth_map). Bad input of any kind must end in a UserError; any other
// exception, a crash, a hang or a sanitizer report is a finding. A scene that loads must be
// checked for the sensor asked for, and a depth map that loads must hold finite distances in range.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <string_view>

#include "core/sensor_registry.h"
#include "core/user_error.h"
#include "scene/depth_map.h"
#include "scene/scene.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  const unsigned kind = data[0] % 5;
  const std::string_view text(reinterpret_cast<const char*>(data) + 1, size - 1);
  try {
    if (kind < 4) {
      const std::string sensor = rangesim::sensors()[kind].id;
      const rangesim::scene::Scene s = rangesim::scene::load_scene_text(text, "fuzz.toml", sensor);
      if (s.sensor != sensor) std::abort();
      if (!std::isfinite(s.distance_m) || !(s.distance_m > 0)) std::abort();
      for (const auto& [key, value] : s.values)
        if (!std::isfinite(value)) std::abort();
    } else {
      const double min_m = 0.1, max_m = 100;
      const rangesim::scene::DepthMap m = rangesim::scene::parse_depth_map(
          text, "fuzz.pgm", "fuzz.toml: target.depth_map_file", 0.5, 2.0, min_m, max_m);
      if (m.width < 1 || m.height < 1 || m.depth_m.size() != static_cast<std::size_t>(m.width) * m.height) std::abort();
      for (double z : m.depth_m)
        if (!(z >= min_m && z <= max_m)) std::abort();
      const double z = m.sample(0, 0, 3, 5);  // resampling stays inside the image
      if (!(z >= min_m && z <= max_m)) std::abort();
    }
  } catch (const rangesim::UserError&) {
    // the expected answer to bad input
  }
  return 0;
}
