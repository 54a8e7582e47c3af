#include "app/compare/compare.h"

#include <chrono>
#include <cmath>
#include <fmt/format.h>

#include "app/cli_common.h"
#include "app/output_dir.h"
#include "app/progress_line.h"
#include <nlohmann/json.hpp>
#include "core/sensor_registry.h"
#include "core/user_error.h"
#include "golden/common/evaluate_sensor.h"
#include "scene/physical.h"

namespace rangesim::app {

namespace {

ProgressLine* g_progress = nullptr;
long long g_done_before = 0, g_total = 0;

void report_progress(int done, int /*total*/) {
  if (g_progress) g_progress->update(g_done_before + done, g_total);
}

std::string key_with_prefix(const ParamSet& p, const std::string& prefix) {
  for (const auto& s : schema_for(p.sensor_id(), p.origin()).params)
    if (s.key.rfind(prefix, 0) == 0) return s.key;
  return "";
}

// The signal axis at exactly one value (native), for the fixed-power profile.
void set_single_signal(ParamSet& p, double native) {
  const ParamSchema& schema = schema_for(p.sensor_id(), p.origin());
  p.set_real(key_with_prefix(p, "evaluation.signal_min_"), native, "--scene source.power_W", schema);
  p.set_real(key_with_prefix(p, "evaluation.signal_max_"), native, "--scene source.power_W", schema);
  p.set_integer("evaluation.signal_points", 1, "--scene source.power_W", schema);
}

}  // namespace

CompareResult run_compare_data(const CompareOptions& opt) {
  const auto t0 = std::chrono::steady_clock::now();
  std::vector<std::string> ids = opt.sensors;
  if (ids.empty())
    for (const auto& s : sensors())
      if (s.radiometry && golden::golden_model(s.id)) ids.push_back(s.id);
  const GridAxis lux = parse_grid_axis(opt.background_lux, "--background-lux");
  const GridAxis watts = parse_grid_axis(opt.signal_power, "--signal-power");
  // Everything is checked before the first evaluation: presets, scene, axes.
  CompareResult r;
  std::vector<ParamSet> grids, profiles;
  for (const auto& id : ids) {
    ParamSet params = load_modelled_preset(id, "compare");
    CompareSensor c;
    c.sensor = params.sensor_id();
    c.preset = id;
    const SensorInfo* info = find_sensor(c.sensor);
    c.title = info->title;
    if (!info->radiometry)
      throw NotModelled{fmt::format("rangesim compare: sensor '{}' has no radiometry (core/radiometry.h): it cannot "
                                    "take a physical scene",
                                    c.sensor)};
    const golden::GoldenModel* model = golden::golden_model(c.sensor);
    c.sbr_definition = model->table_column && model->table_column->sbr_total ? "total" : "ratio";
    const scene::Scene sc = physical_scene(opt.scene, c.sensor);
    r.scene_file = sc.file, r.scene_name = sc.name, r.scene_description = sc.description;
    r.scene_distance_m = sc.distance_m;
    c.axes = physical_axes(params, sc, true);
    c.accuracy_distance_m = params.real(c.axes.radiometry.distance_key);
    c.scene_lux = sc.light.spectral_irradiance_W_per_m2_nm >= 0
                      ? scene::native_light(sc, c.axes.radiometry).background / c.axes.native_per_lux
                      : sc.light.illuminance_lux;
    c.scene_power_W = sc.light.source_power_W;
    c.scene_signal = c.scene_power_W * c.axes.native_per_W;
    c.scene_background = scene::native_light(sc, c.axes.radiometry).background;
    ParamSet g = params;
    apply_physical_axis(g, "signal", opt.signal_power, c.axes.native_per_W, "--signal-power");
    apply_physical_axis(g, "background", opt.background_lux, c.axes.native_per_lux, "--background-lux");
    ParamSet p = params;
    set_single_signal(p, c.scene_signal);
    apply_physical_axis(p, "background",
                        fmt::format("{:.17g}:{:.17g}:{}", lux.lo, lux.hi, opt.profile_points), c.axes.native_per_lux,
                        "--background-lux");
    info->validate(g);
    info->validate(p);
    c.frame_rate_Hz = golden::frame_timing_for(params).range_maps_per_s;
    grids.push_back(g);
    profiles.push_back(p);
    r.sensors.push_back(std::move(c));
  }
  (void)watts;
  ProgressLine progress("compare", "operating points");
  g_progress = &progress;
  g_total = 0;
  for (size_t i = 0; i < grids.size(); ++i)
    g_total += grids[i].integer("evaluation.signal_points") * grids[i].integer("evaluation.background_points") +
               profiles[i].integer("evaluation.background_points");
  g_done_before = 0;
  for (size_t i = 0; i < r.sensors.size(); ++i) {
    CompareSensor& c = r.sensors[i];
    progress.set_label("compare " + c.sensor);
    c.grid = golden::evaluate_sensor(grids[i], &report_progress);
    g_done_before += static_cast<long long>(c.grid.grid_points());
    c.profile = golden::evaluate_sensor(profiles[i], &report_progress);
    g_done_before += static_cast<long long>(c.profile.grid_points());
    const golden::EvalRange& br = c.profile.background_range;
    if (br.range_dB > 0 || std::isfinite(br.lo)) {
      c.bg_lo_lux = br.lo / c.axes.native_per_lux, c.bg_hi_lux = br.hi / c.axes.native_per_lux;
      c.bg_lo_grid = br.lo_limited_by_grid, c.bg_hi_grid = br.hi_limited_by_grid;
    }
    // The scene's own operating point: the profile point nearest its illuminance.
    size_t best = 0;
    for (size_t ib = 0; ib < c.profile.background.values.size(); ++ib)
      if (std::abs(std::log(c.profile.background.values[ib] / c.scene_background)) <
          std::abs(std::log(c.profile.background.values[best] / c.scene_background)))
        best = ib;
    if (!c.profile.points.empty() && c.scene_background > 0) {
      c.scene_detect = c.profile.at(best, 0).detect;
      c.scene_accuracy_m = c.profile.at(best, 0).accuracy_m;
    }
  }
  progress.update(g_total, g_total);
  g_progress = nullptr;
  r.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

}  // namespace rangesim::app

namespace rangesim::app {

std::string write_compare(OutputDir& out, const CompareResult& r, const CompareOptions& opt);
std::string compare_text(const CompareResult& r);
nlohmann::json compare_json(const CompareResult& r, const CompareOptions& opt);

int run_compare(const CompareOptions& opt) {
  const std::string dir = opt.out.empty() ? "rangesim-out/compare" : opt.out;
  OutputDir out(dir, "--out", {"compare", opt.force});
  const CompareResult r = run_compare_data(opt);
  for (const auto& c : r.sensors)
    for (const auto& n : c.axes.notes) fmt::print(stderr, "rangesim compare: note: {}: {}\n", c.sensor, n);
  const std::string warning = write_compare(out, r, opt);
  const std::vector<std::string> written = out.commit();
  if (!warning.empty()) fmt::print(stderr, "rangesim compare: warning: {}\n", warning);
  if (opt.json) {
    nlohmann::json j = compare_json(r, opt);
    j["files"] = written;
    fmt::print("{}\n", j.dump(2));
    return 0;
  }
  fmt::print("{}outputs in {}/: ", compare_text(r), dir);
  for (size_t i = 0; i < written.size(); ++i)
    fmt::print("{}{}", i ? ", " : "", written[i].substr(written[i].find_last_of('/') + 1));
  fmt::print("\n");
  return 0;
}

}  // namespace rangesim::app
