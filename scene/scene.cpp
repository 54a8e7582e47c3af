#include "scene/scene.h"

#include <cmath>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <map>
#include <set>
#include <toml++/toml.h>

#include "core/user_error.h"

namespace rangesim::scene {

const char* shape_name(TargetShape s) {
  switch (s) {
    case TargetShape::Plane: return "plane";
    case TargetShape::Tilted: return "tilted";
    case TargetShape::Step: return "step";
  }
  return "?";
}

namespace {

std::string where(const std::string& file, const toml::node& node) {
  const auto& src = node.source();
  return src.begin.line == 0 ? file : fmt::format("{}:{}", file, src.begin.line);
}

struct Range {
  double lo, hi;
  bool lo_open, hi_open;
  std::string text() const {
    return fmt::format("{}{:g}, {:g}{}", lo_open ? "(" : "[", lo, hi, hi_open ? ")" : "]");
  }
  bool contains(double v) const {
    return std::isfinite(v) && (lo_open ? v > lo : v >= lo) && (hi_open ? v < hi : v <= hi);
  }
};

// The keys a scene may have: section.key -> allowed range (numbers) or empty (strings).
struct KeySpec {
  bool number;
  Range range;
};

const std::map<std::string, KeySpec>& key_specs() {
  static const std::map<std::string, KeySpec> specs = {
      {"scene.name", {false, {}}},
      {"scene.description", {false, {}}},
      {"target.shape", {false, {}}},
      {"target.distance_m", {true, {0.01, 1e4, false, false}}},
      {"target.reflectance", {true, {0, 1, true, false}}},
      {"target.tilt_x_rad", {true, {-1.5, 1.5, false, false}}},
      {"target.tilt_y_rad", {true, {-1.5, 1.5, false, false}}},
      {"target.near_distance_m", {true, {0.01, 1e4, false, false}}},
      {"target.step_y_m", {true, {-1e3, 1e3, false, false}}},
      {"beam.power_W", {true, {0, 100, true, false}}},
      {"beam.reference_distance_m", {true, {0.01, 1e4, false, false}}},
      {"beam.column_offset_px", {true, {-1, 1, false, false}}},
      {"background.irradiance_W_per_m2", {true, {0, 1e4, false, false}}},
      {"camera.f_number", {true, {0.5, 64, false, false}}},
      {"camera.fill_factor", {true, {0, 1, true, false}}},
      {"camera.responsivity_A_per_W", {true, {0, 2, true, false}}},
  };
  return specs;
}

std::string allowed_in(const std::string& section) {
  std::string s;
  for (const auto& [k, _] : key_specs())
    if (k.rfind(section + ".", 0) == 0) s += (s.empty() ? "" : ", ") + k;
  return s.empty() ? "(no such section; sections: scene, target, beam, background, camera)" : s;
}

}  // namespace

Scene load_scene(const std::string& path) {
  if (!std::filesystem::is_regular_file(path)) throw UserError(fmt::format("--scene {}: cannot read scene file (no such file)", path));
  std::ifstream in(path);
  if (!in) throw UserError(fmt::format("--scene {}: cannot read scene file", path));
  toml::table root;
  try {
    root = toml::parse(in, path);
  } catch (const toml::parse_error& e) {
    throw UserError(fmt::format("{}:{}:{}: TOML syntax error: {}", path, e.source().begin.line, e.source().begin.column,
                                e.description()));
  }
  std::map<std::string, double> num;
  std::map<std::string, std::string> text;
  for (const auto& [section_key, section_node] : root) {
    const std::string section(section_key.str());
    const toml::table* t = section_node.as_table();
    if (!t) throw UserError(fmt::format("{}: top-level key '{}' must be a [section]; sections: scene, target, beam, background, camera",
                                        where(path, section_node), section));
    for (const auto& [k, node] : *t) {
      const std::string key = section + "." + std::string(k.str());
      const auto it = key_specs().find(key);
      if (it == key_specs().end())
        throw UserError(fmt::format("{}: unknown key '{}'; allowed in [{}]: {}", where(path, node), key, section,
                                    allowed_in(section)));
      if (it->second.number) {
        double v;
        if (auto d = node.value_exact<double>()) v = *d;
        else if (auto i = node.value_exact<int64_t>()) v = static_cast<double>(*i);
        else throw UserError(fmt::format("{}: {} must be a number in {}", where(path, node), key, it->second.range.text()));
        if (!it->second.range.contains(v))
          throw UserError(fmt::format("{}: {} = {:g} is out of range; allowed: {}", where(path, node), key, v,
                                      it->second.range.text()));
        num[key] = v;
      } else {
        auto s = node.value_exact<std::string>();
        if (!s) throw UserError(fmt::format("{}: {} must be a string", where(path, node), key));
        text[key] = *s;
      }
    }
  }
  auto need = [&](const std::string& key, const std::string& why) {
    if (!num.count(key) && !text.count(key))
      throw UserError(fmt::format("{}: missing key '{}' ({}{})", path, key, why,
                                  key_specs().at(key).number ? "; allowed: " + key_specs().at(key).range.text() : ""));
  };
  auto forbid = [&](const std::string& key, const std::string& shape) {
    if (num.count(key))
      throw UserError(fmt::format("{}: key '{}' does not apply to target.shape = \"{}\"", path, key, shape));
  };
  Scene s;
  s.file = path;
  need("scene.name", "a name for the outputs");
  s.name = text["scene.name"];
  if (s.name.empty()) throw UserError(fmt::format("{}: scene.name must not be empty", path));
  s.description = text.count("scene.description") ? text["scene.description"] : "";
  need("target.shape", "plane, tilted or step");
  const std::string shape = text["target.shape"];
  if (shape == "plane") s.shape = TargetShape::Plane;
  else if (shape == "tilted") s.shape = TargetShape::Tilted;
  else if (shape == "step") s.shape = TargetShape::Step;
  else throw UserError(fmt::format("{}: target.shape = \"{}\" is not allowed; allowed: plane, tilted, step", path, shape));
  for (const char* k : {"target.distance_m", "target.reflectance", "beam.power_W", "beam.reference_distance_m",
                        "background.irradiance_W_per_m2", "camera.f_number", "camera.fill_factor",
                        "camera.responsivity_A_per_W"})
    need(k, "required");
  s.distance_m = num["target.distance_m"];
  s.reflectance = num["target.reflectance"];
  s.beam_power_W = num["beam.power_W"];
  s.reference_distance_m = num["beam.reference_distance_m"];
  s.column_offset_px = num.count("beam.column_offset_px") ? num["beam.column_offset_px"] : 0.0;
  s.background_irradiance_W_per_m2 = num["background.irradiance_W_per_m2"];
  s.f_number = num["camera.f_number"];
  s.fill_factor = num["camera.fill_factor"];
  s.responsivity_A_per_W = num["camera.responsivity_A_per_W"];
  switch (s.shape) {
    case TargetShape::Plane:
      for (const char* k : {"target.tilt_x_rad", "target.tilt_y_rad", "target.near_distance_m", "target.step_y_m"})
        forbid(k, shape);
      break;
    case TargetShape::Tilted:
      for (const char* k : {"target.near_distance_m", "target.step_y_m"}) forbid(k, shape);
      need("target.tilt_x_rad", "tilted: rotation about the vertical axis");
      need("target.tilt_y_rad", "tilted: rotation about the horizontal axis");
      s.tilt_x_rad = num["target.tilt_x_rad"];
      s.tilt_y_rad = num["target.tilt_y_rad"];
      break;
    case TargetShape::Step:
      for (const char* k : {"target.tilt_x_rad", "target.tilt_y_rad"}) forbid(k, shape);
      need("target.near_distance_m", "step: depth of the near face");
      need("target.step_y_m", "step: the near face covers y > step_y_m");
      s.near_distance_m = num["target.near_distance_m"];
      s.step_y_m = num["target.step_y_m"];
      if (!(s.near_distance_m < s.distance_m))
        throw UserError(fmt::format("{}: target.near_distance_m = {:g} must be < target.distance_m = {:g} (the far wall)",
                                    path, s.near_distance_m, s.distance_m));
      break;
  }
  return s;
}

}  // namespace rangesim::scene
