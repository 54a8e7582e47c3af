#include "systemc/tof_lockin/lockin_scene.h"

#include <fmt/format.h>
#include <fstream>
#include <optional>
#include <set>
#include <toml++/toml.h>

#include "core/user_error.h"
#include "golden/tof_lockin/pulse_timing.h"

namespace rangesim::systemc::lockin {

namespace {

struct Reader {
  const std::string &file;
  const toml::table &root;

  const toml::node *node(const std::string &key) const {
    return root.at_path(key).node();
  }
  double real(const std::string &key, double lo, double hi, bool lo_open,
              double fallback, bool required, const char *unit) const {
    const toml::node *n = node(key);
    if (!n) {
      if (required)
        throw UserError(fmt::format(
            "{}: missing key {} (a number in {}, {} {} .. {})", file, key, unit,
            lo_open ? "allowed >" : "allowed", lo, hi));
      return fallback;
    }
    std::optional<double> v = n->value<double>();
    if (!v)
      throw UserError(
          fmt::format("{}: key {} must be a number ({})", file, key, unit));
    if (!(lo_open ? *v > lo : *v >= lo) || !(*v <= hi))
      throw UserError(
          fmt::format("{}: key {} = {:g} {}; allowed {}{:g} .. {:g} {}", file,
                      key, *v, unit, lo_open ? "> " : "", lo, hi, unit));
    return *v;
  }
  int integer(const std::string &key, int lo, int hi) const {
    const toml::node *n = node(key);
    if (!n)
      return 0;
    std::optional<long long> v = n->value<long long>();
    if (!v || *v < lo || *v > hi)
      throw UserError(
          fmt::format("{}: key {} must be an integer; allowed {} .. {}", file,
                      key, lo, hi));
    return static_cast<int>(*v);
  }
  std::string str(const std::string &key, const std::string &fallback) const {
    const toml::node *n = node(key);
    if (!n)
      return fallback;
    std::optional<std::string> v = n->value<std::string>();
    if (!v)
      throw UserError(fmt::format("{}: key {} must be a string", file, key));
    return *v;
  }
};

} // namespace

const char *shape_name(LockinScene::Shape s) {
  return s == LockinScene::Shape::Plane ? "plane" : "step";
}

LockinScene load_lockin_scene(const std::string &path) {
  toml::table root;
  try {
    root = toml::parse_file(path);
  } catch (const toml::parse_error &e) {
    const auto &src = e.source();
    if (src.begin.line == 0 && !std::ifstream(path))
      throw UserError(fmt::format("{}: cannot read the scene file", path));
    throw UserError(fmt::format("{}:{}:{}: {}", path, src.begin.line,
                                src.begin.column, e.description()));
  }
  // Unknown keys are errors (a typo must not silently fall back to a default).
  const std::set<std::string> known = {"scene.name",
                                       "scene.description",
                                       "target.shape",
                                       "target.distance_m",
                                       "target.near_distance_m",
                                       "target.step_column_fraction",
                                       "light.signal_photocurrent_A",
                                       "light.reference_distance_m",
                                       "light.background_photocurrent_A",
                                       "window.rows",
                                       "window.columns"};
  for (const auto &[sec, tbl] : root) {
    if (!tbl.is_table())
      throw UserError(fmt::format("{}: key {} is not in a table; allowed "
                                  "tables [scene] [target] [light] [window]",
                                  path, std::string(sec.str())));
    for (const auto &[k, v] : *tbl.as_table()) {
      const std::string key =
          std::string(sec.str()) + "." + std::string(k.str());
      if (!known.count(key))
        throw UserError(fmt::format(
            "{}: unknown key {}; allowed: scene.name, scene.description, "
            "target.shape, "
            "target.distance_m, target.near_distance_m, "
            "target.step_column_fraction, "
            "light.signal_photocurrent_A, light.reference_distance_m, "
            "light.background_photocurrent_A, window.rows, window.columns",
            path, key));
    }
  }
  const Reader r{path, root};
  LockinScene s;
  s.file = path;
  s.name = r.str("scene.name", "");
  if (s.name.empty())
    throw UserError(
        fmt::format("{}: missing key scene.name (a non-empty string)", path));
  if (s.name.find_first_of("/\\") != std::string::npos || s.name == "." ||
      s.name == "..")
    throw UserError(fmt::format(
        "{}: key scene.name = \"{}\"; allowed: a name without '/' or '\\'",
        path, s.name));
  s.description = r.str("scene.description", "");
  const std::string shape = r.str("target.shape", "plane");
  if (shape == "plane")
    s.shape = LockinScene::Shape::Plane;
  else if (shape == "step")
    s.shape = LockinScene::Shape::Step;
  else
    throw UserError(fmt::format(
        "{}: key target.shape = \"{}\"; allowed \"plane\", \"step\"", path,
        shape));
  s.distance_m = r.real("target.distance_m", 0.0, 1000.0, true, 0, true, "m");
  if (s.shape == LockinScene::Shape::Step) {
    s.near_distance_m =
        r.real("target.near_distance_m", 0.0, 1000.0, true, 0, true, "m");
    s.step_column_fraction =
        r.real("target.step_column_fraction", 0.0, 1.0, false, 0.5, false, "");
  }
  s.signal_photocurrent_A =
      r.real("light.signal_photocurrent_A", 0.0, 1e-6, false, 0, true, "A");
  s.reference_distance_m =
      r.real("light.reference_distance_m", 0.0, 1000.0, true, 1.0, false, "m");
  s.background_photocurrent_A = r.real("light.background_photocurrent_A", 0.0,
                                       1e-6, false, 0.0, false, "A");
  s.rows = r.integer("window.rows", 0, 4096);
  s.columns = r.integer("window.columns", 0, 4096);
  return s;
}

double LockinScene::distance_at(int /*r*/, int c, int array_columns) const {
  if (shape == Shape::Step && c < step_column_fraction * array_columns)
    return near_distance_m;
  return distance_m;
}

std::vector<LockinPixelStimulus>
LockinScene::stimulus(const TofLockinConfig &cfg) const {
  const int R = window_rows(cfg), C = window_columns(cfg);
  std::vector<LockinPixelStimulus> st;
  st.reserve(static_cast<std::size_t>(R) * C);
  for (int r = 0; r < R; ++r)
    for (int c = 0; c < C; ++c) {
      const double d = distance_at(r, c, C);
      const double k = reference_distance_m / d;
      st.push_back({signal_photocurrent_A * k * k, background_photocurrent_A,
                    golden::round_trip_delay_s(d)});
    }
  return st;
}

} // namespace rangesim::systemc::lockin
