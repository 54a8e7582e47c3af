#include "scene/scene.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fmt/format.h>
#include <map>
#include <optional>
#include <set>
#include <toml++/toml.h>
#include <vector>

#include "core/sensor_registry.h"
#include "core/input_file.h"
#include "core/user_error.h"
#include "scene/light.h"

namespace rangesim::scene {

const char* shape_name(TargetShape s) {
  switch (s) {
    case TargetShape::Plane: return "plane";
    case TargetShape::Tilted: return "tilted";
    case TargetShape::Step: return "step";
    case TargetShape::DepthMap: return "depth_map";
    case TargetShape::Objects: return "objects";
  }
  return "?";
}

namespace {

namespace fs = std::filesystem;

std::string where(const std::string& file, const toml::node& node) {
  const auto& src = node.source();
  return src.begin.line == 0 ? file : fmt::format("{}:{}", file, src.begin.line);
}

struct Range {
  double lo, hi;
  bool lo_open, hi_open;
  std::string text() const { return fmt::format("{}{:g}, {:g}{}", lo_open ? "(" : "[", lo, hi, hi_open ? ")" : "]"); }
  bool contains(double v) const {
    return std::isfinite(v) && (lo_open ? v > lo : v >= lo) && (hi_open ? v < hi : v <= hi);
  }
};

enum class Kind { Number, Integer, Text };

struct KeySpec {
  Kind kind;
  Range range;  // numbers and integers
  bool common;  // every sensor's scenes have it; others belong to the sensors whose SceneRules list them
};

const std::map<std::string, KeySpec>& key_specs() {
  static const std::map<std::string, KeySpec> specs = {
      {"scene.name", {Kind::Text, {}, true}},
      {"scene.description", {Kind::Text, {}, true}},
      {"target.shape", {Kind::Text, {}, true}},
      {"target.distance_m", {Kind::Number, {0.01, 1e4, false, false}, true}},
      {"target.depth_map_file", {Kind::Text, {}, true}},
      {"target.depth_near_m", {Kind::Number, {0.01, 1e4, false, false}, true}},
      {"target.depth_far_m", {Kind::Number, {0.01, 1e4, false, false}, true}},
      {"target.reflectance", {Kind::Number, {0, 1, true, false}, true}},
      {"target.tilt_x_rad", {Kind::Number, {-1.5, 1.5, false, false}, false}},
      {"target.tilt_y_rad", {Kind::Number, {-1.5, 1.5, false, false}, false}},
      {"target.near_distance_m", {Kind::Number, {0.01, 1e4, false, false}, false}},
      {"target.step_y_m", {Kind::Number, {-1e3, 1e3, false, false}, false}},
      {"target.step_column_fraction", {Kind::Number, {0, 1, false, false}, false}},
      {"target.step_distance_m", {Kind::Number, {0.01, 1e4, false, false}, false}},
      {"target.step_column", {Kind::Integer, {0, 4096, false, false}, false}},
      {"target.tilt_m_per_row", {Kind::Number, {-0.01, 0.01, false, false}, false}},
      {"beam.power_W", {Kind::Number, {0, 100, true, false}, false}},
      {"beam.reference_distance_m", {Kind::Number, {0.01, 1e4, false, false}, false}},
      {"beam.column_offset_px", {Kind::Number, {-1, 1, false, false}, false}},
      {"beam.signal_A", {Kind::Number, {0, 1e-6, false, false}, false}},
      {"beam.first_column_px", {Kind::Number, {-1000, 4096, false, false}, false}},
      {"beam.columns_per_frame", {Kind::Number, {-10, 10, false, false}, false}},
      {"beam.first_row", {Kind::Integer, {0, 4096, false, false}, true}},
      {"beam.rows", {Kind::Integer, {0, 4096, false, false}, true}},
      {"beam.first_column", {Kind::Integer, {0, 4096, false, false}, true}},
      {"beam.columns", {Kind::Integer, {0, 4096, false, false}, true}},
      {"light.signal_photocurrent_A", {Kind::Number, {0, 1e-6, false, false}, false}},
      {"light.reference_distance_m", {Kind::Number, {0, 1000, true, false}, false}},
      {"light.background_photocurrent_A", {Kind::Number, {0, 1e-6, false, false}, false}},
      {"rates.signal_Hz", {Kind::Number, {0, 5e7, false, false}, false}},
      {"rates.reference_distance_m", {Kind::Number, {0.1, 1e3, false, false}, false}},
      {"rates.background_Hz", {Kind::Number, {0, 1e9, false, false}, false}},
      {"background.irradiance_W_per_m2", {Kind::Number, {0, 1e4, false, false}, false}},
      {"background.photocurrent_A", {Kind::Number, {0, 1e-5, false, false}, false}},
      {"camera.f_number", {Kind::Number, {0.5, 64, false, false}, true}},
      {"camera.filter_bandwidth_m", {Kind::Number, {0, 1e-6, true, false}, true}},
      {"ambient.illuminance_lux", {Kind::Number, {0, 1e6, false, false}, true}},
      {"ambient.spectrum", {Kind::Text, {}, true}},
      {"ambient.spectral_irradiance_W_per_m2_nm", {Kind::Number, {0, 100, false, false}, true}},
      {"source.power_W", {Kind::Number, {0, 100, true, false}, true}},
      {"source.wavelength_m", {Kind::Number, {300e-9, 2e-6, false, false}, true}},
      {"source.beam", {Kind::Text, {}, true}},
      {"source.pulse_width_s", {Kind::Number, {0, 1e-3, true, false}, true}},
      {"source.modulation_Hz", {Kind::Number, {0, 1e9, true, false}, true}},
      {"camera.fill_factor", {Kind::Number, {0, 1, true, false}, false}},
      {"camera.responsivity_A_per_W", {Kind::Number, {0, 2, true, false}, false}},
      {"window.first_row", {Kind::Integer, {0, 4096, false, false}, false}},
      {"window.rows", {Kind::Integer, {0, 4096, false, false}, false}},
      {"window.first_column", {Kind::Integer, {0, 4096, false, false}, false}},
      {"window.columns", {Kind::Integer, {0, 4096, false, false}, false}},
  };
  return specs;
}

// The sensor a scene is read for, and what its scenes may hold (core/scene_rules.h).
struct SensorScene {
  const std::string& id;
  const SceneRules& rules;
  bool rasterises;  // the sensor has a radiometry (core/radiometry.h): it takes every shape
  bool allows(const std::string& key, const KeySpec& spec) const {
    return spec.common || std::find(rules.keys.begin(), rules.keys.end(), key) != rules.keys.end();
  }
};

std::string join(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : ", ") + x;
  return s;
}

std::string allowed_in(const std::string& section, const SensorScene& sensor) {
  std::string s;
  for (const auto& [k, spec] : key_specs())
    if (k.rfind(section + ".", 0) == 0 && sensor.allows(k, spec)) s += (s.empty() ? "" : ", ") + k;
  return s.empty() ? "(none for this sensor)" : s;
}

std::string sections_of(const SensorScene& sensor) {
  std::vector<std::string> v;
  for (const auto& [k, spec] : key_specs()) {
    const std::string sec = k.substr(0, k.find('.'));
    if (sensor.allows(k, spec) && (v.empty() || v.back() != sec)) v.push_back(sec);
  }
  return join(v);
}

Scene parse(const toml::table& root, const std::string& path, const SensorScene& sensor) {
  const SceneRules& rules = sensor.rules;
  std::map<std::string, std::string> text;
  Scene s;
  s.file = path;
  s.sensor = sensor.id;
  std::map<std::string, int> line_of;
  for (const auto& [section_key, section_node] : root) {
    const std::string section(section_key.str());
    if (section == "object") {  // [[object]]: the objects of target.shape = "objects"
      const toml::array* a = section_node.as_array();
      if (!a || !a->is_array_of_tables())
        throw UserError(fmt::format("{}: 'object' must be an array of tables, [[object]]", where(path, section_node)));
      for (const auto& item : *a) {
        SceneObject o;
        std::map<std::string, double> v;
        for (const auto& [k, node] : *item.as_table()) {
          const std::string key(k.str());
          const bool distance = key == "distance_m";
          if (!distance && key != "left" && key != "right" && key != "top" && key != "bottom")
            throw UserError(fmt::format("{}: unknown key 'object.{}'; allowed in [[object]]: distance_m, left, right, "
                                        "top, bottom",
                                        where(path, node), key));
          std::optional<double> d = node.value<double>();
          const double lo = distance ? 0.01 : 0.0, hi = distance ? 1e4 : 1.0;
          if (!d || !std::isfinite(*d) || *d < lo || *d > hi)
            throw UserError(fmt::format("{}: object.{} must be a number in [{:g}, {:g}]{}", where(path, node), key, lo,
                                        hi, distance ? " m" : " (a fraction of the field of view)"));
          v[key] = *d;
        }
        if (!v.count("distance_m"))
          throw UserError(fmt::format("{}: missing key 'object.distance_m' in an [[object]]; allowed: [0.01, 10000]",
                                      where(path, item)));
        o.distance_m = v["distance_m"];
        o.left = v.count("left") ? v["left"] : 0.0, o.right = v.count("right") ? v["right"] : 1.0;
        o.top = v.count("top") ? v["top"] : 0.0, o.bottom = v.count("bottom") ? v["bottom"] : 1.0;
        if (!(o.left < o.right) || !(o.top < o.bottom))
          throw UserError(fmt::format("{}: an [[object]] needs left < right and top < bottom (fractions of the field "
                                      "of view); got left {:g}, right {:g}, top {:g}, bottom {:g}",
                                      where(path, item), o.left, o.right, o.top, o.bottom));
        s.objects.push_back(o);
      }
      continue;
    }
    const toml::table* t = section_node.as_table();
    if (!t)
      throw UserError(fmt::format("{}: top-level key '{}' must be a [section]; sections of a {} scene: {}",
                                  where(path, section_node), section, sensor.id, sections_of(sensor)));
    for (const auto& [k, node] : *t) {
      const std::string key = section + "." + std::string(k.str());
      const auto it = key_specs().find(key);
      if (it == key_specs().end())
        throw UserError(fmt::format("{}: unknown key '{}'; allowed in [{}] of a {} scene: {}", where(path, node), key,
                                    section, sensor.id, allowed_in(section, sensor)));
      const KeySpec& spec = it->second;
      if (!sensor.allows(key, spec))
        s.notes.push_back(fmt::format("{}: {} is not used by {} (a key of other sensors' scenes)", where(path, node),
                                      key, sensor.id));
      line_of[key] = static_cast<int>(node.source().begin.line);
      if (spec.kind == Kind::Text) {
        auto v = node.value_exact<std::string>();
        if (!v) throw UserError(fmt::format("{}: {} must be a string", where(path, node), key));
        text[key] = *v;
        s.texts[key] = *v;
        continue;
      }
      double v;
      if (auto i = node.value_exact<int64_t>())
        v = static_cast<double>(*i);
      else if (auto d = node.value_exact<double>(); d && spec.kind == Kind::Number)
        v = *d;
      else
        throw UserError(fmt::format("{}: {} must be {} in {}", where(path, node), key,
                                    spec.kind == Kind::Integer ? "an integer" : "a number", spec.range.text()));
      if (!spec.range.contains(v))
        throw UserError(
            fmt::format("{}: {} = {:g} is out of range; allowed: {}", where(path, node), key, v, spec.range.text()));
      s.values[key] = v;
    }
  }
  auto need = [&](const std::string& key, const std::string& why) {
    if (!s.values.count(key) && !text.count(key)) {
      const KeySpec& spec = key_specs().at(key);
      throw UserError(fmt::format("{}: missing key '{}' ({}{})", path, key, why,
                                  spec.kind == Kind::Text ? "" : "; allowed: " + spec.range.text()));
    }
  };
  // The physical light ([ambient] / [source]) stands for the sensor's own light keys.
  s.light.present = text.count("source.beam") || text.count("ambient.spectrum") ||
                    std::any_of(s.values.begin(), s.values.end(), [](const auto& kv) {
                      return kv.first.rfind("ambient.", 0) == 0 || kv.first.rfind("source.", 0) == 0;
                    });
  if (!s.light.present)
    for (const auto& k : rules.required)
      need(k, "required in a " + sensor.id + " scene (or give the light physically: [ambient], [source])");
  if (s.light.present) {
    need("source.power_W", "the active source's mean optical power");
    PhysicalLight& l = s.light;
    l.illuminance_lux = s.get("ambient.illuminance_lux", 0);
    l.spectrum = text.count("ambient.spectrum") ? text["ambient.spectrum"] : "sunlight";
    if (!known_spectrum(l.spectrum)) {
      std::string names;
      for (const auto& n : spectrum_names()) names += (names.empty() ? "\"" : ", \"") + n + "\"";
      throw UserError(fmt::format("{}:{}: ambient.spectrum = \"{}\" is not a known spectrum; allowed: {}", path,
                                  line_of["ambient.spectrum"], l.spectrum, names));
    }
    if (s.has("ambient.spectral_irradiance_W_per_m2_nm")) {
      if (s.has("ambient.illuminance_lux") || text.count("ambient.spectrum"))
        throw UserError(fmt::format(
            "{}: ambient.spectral_irradiance_W_per_m2_nm and ambient.illuminance_lux / ambient.spectrum exclude "
            "each other; give the ambient light one way",
            path));
      l.spectral_irradiance_W_per_m2_nm = s.values["ambient.spectral_irradiance_W_per_m2_nm"];
    }
    l.source_power_W = s.values["source.power_W"];
    l.wavelength_m = s.get("source.wavelength_m", 0);
    const std::string beam = text.count("source.beam") ? text["source.beam"] : "sheet";
    if (beam != "sheet" && beam != "flood" && beam != "spot")
      throw UserError(fmt::format("{}:{}: source.beam = \"{}\"; allowed: \"sheet\", \"flood\", \"spot\"", path,
                                  line_of["source.beam"], beam));
    l.beam = beam == "flood" ? BeamShape::Flood : beam == "spot" ? BeamShape::Spot : BeamShape::Sheet;
    l.filter_bandwidth_m = s.get("camera.filter_bandwidth_m", l.filter_bandwidth_m);
    for (const char* k : {"source.pulse_width_s", "source.modulation_Hz"})
      if (s.has(k))
        s.notes.push_back(fmt::format("{}:{}: {} is not used by {}: its timing is the preset's", path, line_of[k], k,
                                      sensor.id));
  } else {
    for (const char* k : {"camera.filter_bandwidth_m"})
      if (s.has(k))
        s.notes.push_back(fmt::format("{}:{}: {} is not used: the scene gives no [ambient] light", path, line_of[k], k));
  }
  s.name = text.count("scene.name") ? text["scene.name"] : fs::path(path).stem().string();
  if (s.name.empty()) throw UserError(fmt::format("{}: scene.name must not be empty", path));
  if (s.name.find_first_of("/\\") != std::string::npos || s.name == "." || s.name == "..")
    throw UserError(fmt::format(
        "{}: scene.name = \"{}\"; allowed: a name without '/' or '\\' (it names the output folder)", path, s.name));
  s.description = text.count("scene.description") ? text["scene.description"] : "";
  const std::string shape = text.count("target.shape") ? text["target.shape"] : "plane";
  bool known_shape = false;
  for (const auto& sh : rules.shapes) known_shape = known_shape || sh == shape;
  const bool any_shape =
      shape == "plane" || shape == "tilted" || shape == "step" || shape == "depth_map" || shape == "objects";
  if (!known_shape && any_shape && sensor.rasterises)
    s.notes.push_back(fmt::format("{}: target.shape = \"{}\" is not modelled natively by {}: rasterised into a depth "
                                  "map at its pixel grid",
                                  path, shape, sensor.id));
  else if (!known_shape)
    throw UserError(fmt::format("{}: target.shape = \"{}\" is not allowed for {}; allowed: {}", path, shape, sensor.id,
                                join(rules.shapes)));
  s.shape = shape == "tilted"      ? TargetShape::Tilted
            : shape == "step"      ? TargetShape::Step
            : shape == "depth_map" ? TargetShape::DepthMap
            : shape == "objects"   ? TargetShape::Objects
                                   : TargetShape::Plane;
  if (s.shape == TargetShape::Objects && s.objects.empty())
    throw UserError(fmt::format("{}: target.shape = \"objects\" needs at least one [[object]] (distance_m, left, "
                                "right, top, bottom)",
                                path));
  if (s.shape != TargetShape::Objects && !s.objects.empty())
    throw UserError(fmt::format("{}: [[object]] tables apply to target.shape = \"objects\" only", path));
  auto forbid = [&](const std::string& key) {
    if (s.values.count(key) || text.count(key))
      throw UserError(fmt::format("{}: key '{}' does not apply to target.shape = \"{}\"", path, key, shape));
  };
  if (s.shape == TargetShape::DepthMap) {
    forbid("target.distance_m");
    need("target.depth_map_file", "depth_map: the image, PGM or PFM");
    fs::path img = text["target.depth_map_file"];
    if (img.is_relative()) img = fs::path(path).parent_path() / img;  // relative to the scene file
    const bool pfm = img.extension() == ".pfm" || img.extension() == ".PFM";
    if (pfm) {
      forbid("target.depth_near_m"), forbid("target.depth_far_m");
    } else {
      need("target.depth_near_m", "depth_map PGM: distance of gray level 0");
      need("target.depth_far_m", "depth_map PGM: distance of gray level maxval");
    }
    const std::string key = fmt::format("{}:{}: target.depth_map_file", path, line_of["target.depth_map_file"]);
    s.depth_map =
        std::make_shared<DepthMap>(load_depth_map(img.lexically_normal().string(), key, s.get("target.depth_near_m", 0),
                                                  s.get("target.depth_far_m", 0), 0.01, 1e4));
    s.distance_m = *std::min_element(s.depth_map->depth_m.begin(), s.depth_map->depth_m.end());
  } else {
    for (const char* k : {"target.depth_map_file", "target.depth_near_m", "target.depth_far_m"}) forbid(k);
    need("target.distance_m", "required unless target.shape = \"depth_map\"");
    s.distance_m = s.values["target.distance_m"];
  }
  // The ls-conventional radiometry and geometry (the other sensors read s.values).
  s.reflectance = s.get("target.reflectance", s.reflectance);
  s.beam_power_W = s.get("beam.power_W", s.beam_power_W);
  s.reference_distance_m = s.get("beam.reference_distance_m", s.reference_distance_m);
  s.column_offset_px = s.get("beam.column_offset_px", 0.0);
  s.background_irradiance_W_per_m2 = s.get("background.irradiance_W_per_m2", 0.0);
  s.f_number = s.get("camera.f_number", s.f_number);
  s.fill_factor = s.get("camera.fill_factor", s.fill_factor);
  s.responsivity_A_per_W = s.get("camera.responsivity_A_per_W", s.responsivity_A_per_W);
  if (s.shape != TargetShape::Tilted)
    for (const char* k : {"target.tilt_x_rad", "target.tilt_y_rad"}) forbid(k);
  if (s.shape != TargetShape::Step)
    for (const char* k : {"target.near_distance_m", "target.step_y_m", "target.step_column_fraction",
                          "target.step_distance_m", "target.step_column"})
      forbid(k);
  if (s.shape == TargetShape::Tilted) {
    need("target.tilt_x_rad", "tilted: rotation about the vertical axis");
    need("target.tilt_y_rad", "tilted: rotation about the horizontal axis");
    s.tilt_x_rad = s.values["target.tilt_x_rad"];
    s.tilt_y_rad = s.values["target.tilt_y_rad"];
  }
  if (s.shape == TargetShape::Step) {
    // The step's edge: a row edge (step_y_m), a column fraction (step_column_fraction) or a column
    // (step_column, with step_distance_m on its right); a sensor rasterises the ones it lacks.
    if (rules.step_y && !s.has("target.step_y_m") && !s.has("target.step_column_fraction") &&
        !s.has("target.step_column") && !s.has("target.step_distance_m"))
      throw UserError(fmt::format(
          "{}: missing key 'target.step_y_m' (step: the near face covers y > step_y_m; or "
          "target.step_column_fraction, or target.step_column with target.step_distance_m)",
          path));
    if (s.has("target.step_distance_m") || s.has("target.step_column")) {
      if (!s.has("target.step_distance_m"))
        throw UserError(fmt::format("{}: missing key 'target.step_distance_m' (step: depth right of step_column)", path));
    } else if (rules.step_near_face || sensor.rasterises) {
      need("target.near_distance_m", "step: depth of the near face");
    }
    s.near_distance_m = s.get("target.near_distance_m", s.distance_m);
    if (s.has("target.step_y_m")) {
      need("target.step_y_m", "step: the near face covers y > step_y_m");
      s.step_y_m = s.values["target.step_y_m"];
      if (!(s.near_distance_m < s.distance_m))
        throw UserError(
            fmt::format("{}: target.near_distance_m = {:g} must be < target.distance_m = {:g} (the far wall)", path,
                        s.near_distance_m, s.distance_m));
    }
  }
  return s;
}

const SensorInfo& sensor_for(const std::string& sensor) {
  if (const SensorInfo* s = find_sensor(sensor)) return *s;
  throw UserError(fmt::format("scene for sensor '{}': allowed {}", sensor, sensor_ids()));
}

}  // namespace

Scene load_scene_text(std::string_view text, const std::string& origin, const std::string& sensor) {
  const SensorInfo& info = sensor_for(sensor);
  toml::table root;
  try {
    root = toml::parse(text, origin);
  } catch (const toml::parse_error& e) {
    throw UserError(fmt::format("{}:{}:{}: TOML syntax error: {}", origin, e.source().begin.line,
                                e.source().begin.column, e.description()));
  }
  try {
    return parse(root, origin, SensorScene{info.id, info.scene, info.radiometry != nullptr});
  } catch (const UserError&) {
    throw;
  } catch (const std::exception& e) {  // e.g. a file-system error while resolving the image path
    throw UserError(fmt::format("{}: {}", origin, e.what()));
  }
}

Scene load_scene(const std::string& path, const std::string& sensor) {
  // A scene is a few kilobytes (a depth map is a file of its own); the cap bounds a mistaken path.
  constexpr std::uintmax_t kMaxSceneBytes = 4u << 20;
  return load_scene_text(read_input_file(path, "scene file", kMaxSceneBytes, "--scene " + path), path, sensor);
}

}  // namespace rangesim::scene
