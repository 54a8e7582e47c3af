#pragma once
// A scene for the clock-level simulation (`rangesim simulate --scene FILE`): the target, the
// sheet-beam light source, the background light and the camera's radiometry. TOML with SI units
// in the key names; scenes/*.toml are examples, docs/simulate.md the reference.
//
//   [scene]      name (string), description (string, optional)
//   [target]     shape = "plane" | "tilted" | "step"; distance_m; reflectance;
//                tilted: tilt_x_rad, tilt_y_rad (depth z = distance + x tan(tilt_x) + y tan(tilt_y));
//                step: near_distance_m, step_y_m (a near face at near_distance_m covers y > step_y_m
//                in front of the wall at distance_m)
//   [beam]       power_W (sheet-beam optical power, spread evenly over the rows);
//                reference_distance_m (beam positions are the angles that put the stripe on
//                column b + column_offset_px of a plane at this depth); column_offset_px (optional, 0)
//   [background] irradiance_W_per_m2 (in the sensor's spectral band, on the target)
//   [camera]     f_number, fill_factor, responsivity_A_per_W
// Focal length, baseline, pixel pitch, array size, integration time and capacitance come from
// the sensor preset.
#include <string>

namespace rangesim::scene {

enum class TargetShape { Plane, Tilted, Step };

struct Scene {
  std::string file;         // where it was loaded from (for messages)
  std::string name;         // [scene] name
  std::string description;  // [scene] description
  // [target]
  TargetShape shape = TargetShape::Plane;
  double distance_m = 1.0;       // depth of the plane at x = y = 0 (step: the far wall)
  double reflectance = 0.5;      // Lambertian albedo
  double tilt_x_rad = 0;         // tilted: dz/dx = tan(tilt_x)
  double tilt_y_rad = 0;         // tilted: dz/dy = tan(tilt_y)
  double near_distance_m = 0;    // step: depth of the near face
  double step_y_m = 0;           // step: the near face covers y > step_y_m
  // [beam]
  double beam_power_W = 0.5e-3;
  double reference_distance_m = 1.1;
  double column_offset_px = 0;
  // [background]
  double background_irradiance_W_per_m2 = 0;
  // [camera]
  double f_number = 1.4;
  double fill_factor = 0.5;
  double responsivity_A_per_W = 0.4;
};

const char* shape_name(TargetShape s);

// Loads and validates a scene file. Throws UserError naming the file (and line), the key and the
// allowed range on any problem: syntax, unknown section or key, missing key, wrong type, range.
Scene load_scene(const std::string& path);

}  // namespace rangesim::scene
