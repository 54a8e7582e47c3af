#pragma once
// What a sensor's scenes may hold (scene/scene.h reads them through the sensor registry): the
// target shapes it models, its own keys beyond the ones every scene has (scene.*, target.shape,
// target.distance_m and the depth-map keys) and the keys it cannot do without. The keys' types
// and ranges are the scene reader's (scene/scene.cpp).
#include <string>
#include <vector>

namespace rangesim {

struct SceneRules {
  std::vector<std::string> shapes;    // "plane", "tilted", "step", "depth_map"
  std::vector<std::string> keys;      // "section.key" the sensor adds to the common keys
  std::vector<std::string> required;  // keys a scene of this sensor must set
  bool step_near_face = false;        // step: target.near_distance_m is the near face's depth
  bool step_y = false;                // step: target.step_y_m bounds the near face, nearer than the wall
};

}  // namespace rangesim
