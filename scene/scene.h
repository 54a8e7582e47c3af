#pragma once
// The one scene reader of `rangesim simulate --scene FILE`, for every sensor: the target, the
// light source, the background light and the camera's radiometry. TOML with SI units in the key
// names; scenes/*.toml are examples, docs/simulate.md the reference. One key table (scene.cpp)
// says which keys exist, their type and range, and which sensors use them:
//
//   [scene]      name, description                                                all sensors
//   [target]     shape = "plane" | "tilted" | "step" | "depth_map"; distance_m        all sensors
//                depth_map: depth_map_file (PGM P2/P5 8/16-bit or PFM, relative to the scene
//                file), depth_near_m / depth_far_m (PGM: gray 0 -> near, maxval -> far)
//                ls-conventional: reflectance; tilted: tilt_x_rad, tilt_y_rad; step:
//                  near_distance_m, step_y_m (the near face covers y > step_y_m)
//                ls-demodulation: tilt_m_per_row
//                tof-lockin step: near_distance_m, step_column_fraction
//                tof-spad step: step_distance_m, step_column
//   [beam]       ls-conventional: power_W, reference_distance_m, column_offset_px
//                ls-demodulation: signal_A, first_column_px, columns_per_frame
//                tof-spad: first_row, rows, first_column, columns (the lit pixels; default all)
//   [light]      tof-lockin: signal_photocurrent_A, reference_distance_m, background_photocurrent_A
//   [rates]      tof-spad: signal_Hz, reference_distance_m, background_Hz
//   [background] ls-conventional: irradiance_W_per_m2; ls-demodulation: photocurrent_A
//   [camera]     ls-conventional, optional: f_number, fill_factor, responsivity_A_per_W override the
//                preset's optics.f_number, pixel.fill_factor, pixel.responsivity_A_per_W
//   [window]     tof-lockin: rows, columns; tof-spad: first_row, rows, first_column, columns
// Focal length, baseline, pixel pitch, array size, integration time and capacitance come from
// the sensor preset.
//
// The physical light (every sensor; scene/physical.h turns it into each sensor's own unit through
// its radiometry, core/radiometry.h; docs/radiometry.md):
//   [ambient]    illuminance_lux with spectrum = "sunlight" | "halogen" | "led", or
//                spectral_irradiance_W_per_m2_nm (flat around the source wavelength), at the target
//   [source]     power_W (mean optical power), wavelength_m, beam = "sheet" | "flood" | "spot"
//                (spot: [beam] first_row, rows, first_column, columns), pulse_width_s and
//                modulation_Hz (the sensor's timing is its preset's; noted)
//   [camera]     filter_bandwidth_m (the narrow-band filter in front of the lens), f_number
//   [target]     reflectance (Lambertian albedo, every sensor); shape = "objects": the wall at
//                distance_m with [[object]] tables in front (distance_m, left, right, top, bottom:
//                fractions of the field of view), rasterised for every sensor
// A key some sensor uses and this one cannot is a note (Scene::notes), not an error; a sensor's own
// light keys ([light], [rates], beam.signal_A, background.*) override the physical light for it.
// Every sensor takes every shape: a shape or step it does not model natively is rasterised into a
// depth map at its own pixel grid (scene/physical.h).
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "scene/depth_map.h"

namespace rangesim::scene {

enum class TargetShape { Plane, Tilted, Step, DepthMap, Objects };

// One object of an "objects" scene: a rectangle facing the sensor at distance_m, covering the
// fractions [left, right) x [top, bottom) of the field of view (0 = left / top edge, 1 = right /
// bottom), in front of the wall at target.distance_m. Nearer objects hide farther ones.
struct SceneObject {
  double distance_m = 1.0;
  double left = 0, right = 1, top = 0, bottom = 1;
};
enum class BeamShape { Sheet, Flood, Spot };

// The light of a physical scene ([ambient], [source], [camera] filter), common to every sensor.
struct PhysicalLight {
  bool present = false;                         // the file has [ambient] or [source]
  double illuminance_lux = 0;                   // ambient illuminance at the target
  std::string spectrum = "sunlight";            // its spectrum (scene/light.h)
  double spectral_irradiance_W_per_m2_nm = -1;  // >= 0: given directly instead of lux
  double source_power_W = 0;                    // mean optical power of the active source
  double wavelength_m = 0;                      // 0: the sensor's own (its preset), else 850 nm
  BeamShape beam = BeamShape::Sheet;
  double filter_bandwidth_m = 10e-9;            // narrow-band filter FWHM in front of the lens
};

struct Scene {
  std::string file;         // where it was loaded from (for messages)
  std::string sensor;       // the sensor the scene was checked for
  std::string name;         // [scene] name
  std::string description;  // [scene] description
  // [target]
  TargetShape shape = TargetShape::Plane;
  double distance_m = 1.0;                    // depth of the plane at x = y = 0 (step: the far wall)
  double reflectance = 0.5;                   // Lambertian albedo
  double tilt_x_rad = 0;                      // tilted: dz/dx = tan(tilt_x)
  double tilt_y_rad = 0;                      // tilted: dz/dy = tan(tilt_y)
  double near_distance_m = 0;                 // step: depth of the near face
  double step_y_m = 0;                        // step: the near face covers y > step_y_m
  std::shared_ptr<const DepthMap> depth_map;  // depth_map: the image, in metres
  std::vector<SceneObject> objects;           // objects: the [[object]] tables, in file order
  // [beam]
  double beam_power_W = 0.5e-3;
  double reference_distance_m = 1.1;
  double column_offset_px = 0;
  // [background]
  double background_irradiance_W_per_m2 = 0;
  // [camera] (when the file sets them: has("camera.f_number") etc.; else the preset's values)
  double f_number = 1.4;
  double fill_factor = 0.5;
  double responsivity_A_per_W = 0.4;
  // [ambient], [source], [camera].filter_bandwidth_m
  PhysicalLight light;
  // Keys this sensor cannot use, each a one-line note (printed, never fatal).
  std::vector<std::string> notes;
  // Every number the file set, by "section.key" (the other sensors' keys are read from here).
  std::map<std::string, double> values;
  // Every text the file set, by "section.key".
  std::map<std::string, std::string> texts;

  bool has(const std::string& key) const { return values.count(key) > 0; }
  double get(const std::string& key, double fallback) const {
    const auto it = values.find(key);
    return it == values.end() ? fallback : it->second;
  }
  // Depth of the depth map at pixel (row, column) of a rows x columns array (bilinear).
  double map_depth_m(int row, int column, int rows, int columns) const {
    return depth_map->sample(row, column, rows, columns);
  }
};

const char* shape_name(TargetShape s);

// Parses and validates scene text for `sensor` (a registered sensor id, core/sensor_registry.h:
// its SceneRules say which shapes and keys its scenes may hold). `origin` names the text in
// messages and anchors relative paths (depth_map_file is resolved against its directory).
// Throws UserError naming the origin (and line), the key and the allowed range on any problem:
// syntax, unknown section or key, missing key, wrong type, range, image. A key of another sensor
// is a note in Scene::notes.
// Never throws anything else for any text (fuzz/ calls it).
Scene load_scene_text(std::string_view text, const std::string& origin, const std::string& sensor);
// The same for a file (a missing or unreadable file is a UserError naming --scene).
Scene load_scene(const std::string& path, const std::string& sensor);

}  // namespace rangesim::scene
