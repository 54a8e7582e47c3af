#include "systemc/tof_spad/scene_adapter.h"

#include <algorithm>
#include <fmt/format.h>
#include <stdexcept>

#include "core/user_error.h"
#include "scene/physical.h"
#include "scene/scene.h"

namespace rangesim::scene {

namespace {

// A scene key that is checked against the preset here (the scene reader checks the generic range).
void check_range(const Scene& s, const std::string& key, double lo, double hi, const std::string& unit) {
  if (!s.has(key)) return;
  const double v = s.get(key, 0);
  if (v < lo || v > hi)
    throw UserError(fmt::format("{}: {} = {:g}: allowed {:g} <= value <= {:g}{}", s.file, key, v, lo, hi,
                                unit.empty() ? "" : " " + unit));
}

}  // namespace

SpadScene load_spad_scene(const std::string& path, const TofSpadConfig& cfg, int array_rows, int array_columns,
                          const SensorRadiometry* radiometry) {
  const auto need_radiometry = [&]() -> const SensorRadiometry& {
    if (!radiometry) throw std::logic_error("load_spad_scene: a physical scene needs the sensor's radiometry");
    return *radiometry;
  };
  Scene in = load_scene(path, "tof-spad");
  const bool native_step =
      in.shape != TargetShape::Step || (!in.has("target.step_y_m") && !in.has("target.step_column_fraction"));
  if (in.shape == TargetShape::Tilted || in.shape == TargetShape::Objects || !native_step)
    in = rasterised(in, need_radiometry());
  SpadScene s;
  s.notes = in.notes;
  s.file = path;
  s.name = in.name;
  s.description = in.description;
  s.shape = shape_name(in.shape);
  // Echo (with +-6 sigma of the pulse) inside the TDC range and the laser period.
  const double period_s = 1.0 / cfg.laser.repetition_rate_Hz;
  const double max_m = 0.5 * phys::kSpeedOfLight_m_per_s * (std::min(period_s, cfg.tdc.full_range_s) - 2e-9);
  // Nearer than 0.3 m is refused; beyond the unambiguous range the echo is aliased (a note).
  const auto alias = [&](const std::string& what, double z) {
    if (z <= max_m || s.alias_period_s > 0) return;
    s.alias_period_s = period_s;
    s.tof_min_s = 2 * 0.3 / phys::kSpeedOfLight_m_per_s;
    s.tof_max_s = 2 * max_m / phys::kSpeedOfLight_m_per_s;
    s.notes.push_back(fmt::format("{}: {} {:g} m is beyond tof-spad's unambiguous range {:g} m: its echo is seen in a "
                                  "later laser period (aliased)",
                                  path, what, z, max_m));
  };
  check_range(in, "target.distance_m", 0.3, 1e4, "m");
  check_range(in, "target.step_distance_m", 0.3, 1e4, "m");
  if (in.shape != TargetShape::DepthMap) {
    alias("target.distance_m", in.distance_m);
    if (in.has("target.step_distance_m")) alias("target.step_distance_m", in.get("target.step_distance_m", 0));
  }
  check_range(in, "target.step_column", 0, array_columns, "");
  s.distance_m = in.distance_m;
  s.step_distance_m = in.get("target.step_distance_m", s.distance_m);
  s.step_column = static_cast<int>(in.get("target.step_column", array_columns / 2));
  if (in.shape == TargetShape::DepthMap) {
    s.map_columns = array_columns;
    s.depth_map_m = in.depth_map->resample(array_rows, array_columns);
    for (double z : s.depth_map_m) {
      if (z < 0.3)
        throw UserError(fmt::format("{}: target.depth_map_file: distance {:g} m; allowed 0.3 m <= distance", path, z));
      alias("the depth map's distance", z);
    }
  }
  s.signal_Hz = in.get("rates.signal_Hz", s.signal_Hz);
  s.reference_distance_m = in.get("rates.reference_distance_m", s.distance_m);
  s.background_Hz = in.get("rates.background_Hz", s.background_Hz);
  bool physical_spot = false;
  NativeLight n;
  const bool own_rates = in.has("rates.signal_Hz") && in.has("rates.background_Hz");
  if (in.light.present && own_rates) {
    s.notes.push_back(fmt::format("{}: [rates] override [ambient] / [source] for tof-spad", path));
  } else if (in.light.present) {
    n = native_light(in, need_radiometry(), &s.notes);
    if (!in.has("rates.signal_Hz")) {
      s.reference_distance_m = s.distance_m;
      s.signal_Hz = n.signal_at(s.distance_m);
    }
    if (!in.has("rates.background_Hz")) s.background_Hz = n.background;
    physical_spot = in.light.beam == BeamShape::Spot;
  }
  auto get_int = [&](const std::string& key, int def, int lo, int hi) {
    check_range(in, key, lo, hi, "");
    return static_cast<int>(in.get(key, def));
  };
  const int cpt = cfg.tdc.columns_per_tdc;
  s.rows = get_int("window.rows", std::min(4, array_rows), 1, array_rows);
  s.first_row = get_int("window.first_row", (array_rows - s.rows) / 2, 0, array_rows - s.rows);
  s.columns = get_int("window.columns", std::min(16, array_columns), cpt, array_columns);
  if (s.columns % cpt != 0)
    throw UserError(
        fmt::format("{}: window.columns = {}: allowed a multiple of tdc.columns_per_tdc = {}", path, s.columns, cpt));
  s.beam_rows = get_int("beam.rows", physical_spot ? n.spot_rows : array_rows, 1, array_rows);
  s.beam_first_row = get_int("beam.first_row", physical_spot ? n.spot_first_row : 0, 0, array_rows - s.beam_rows);
  s.beam_columns = get_int("beam.columns", physical_spot ? n.spot_columns : array_columns, 1, array_columns);
  s.beam_first_column =
      get_int("beam.first_column", physical_spot ? n.spot_first_column : 0, 0, array_columns - s.beam_columns);
  const int default_first = ((array_columns - s.columns) / 2) / cpt * cpt;
  s.first_column = get_int("window.first_column", default_first, 0, array_columns - s.columns);
  if (s.first_column % cpt != 0)
    throw UserError(
        fmt::format("{}: window.first_column = {}: allowed a multiple of tdc.columns_per_tdc = {} (TDC group edge)",
                    path, s.first_column, cpt));
  return s;
}

}  // namespace rangesim::scene
