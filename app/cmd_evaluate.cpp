// rangesim evaluate: the thesis's background-light and range-accuracy evaluation over a
// log-spaced signal x background grid, written as CSV maps, summary.json and plots.
#include <algorithm>
#include <fmt/format.h>

#include "app/cli_common.h"
#include "app/commands.h"
#include "app/evaluate_params.h"
#include "app/evaluation_output.h"
#include "app/grid_writer.h"
#include "app/output_dir.h"
#include "app/physical_axes.h"
#include "app/plot.h"
#include "app/progress_line.h"
#include "app/run_control.h"
#include "core/preset.h"
#include "core/user_error.h"
#include "golden/common/evaluate_sensor.h"

namespace rangesim::app {

namespace {

// Golden models report progress through a plain function pointer, hence the one line here.
ProgressLine* g_progress = nullptr;
double g_grid_start_s = 0;  // seconds since the start of the process when the grid began

// A run that cannot finish within --max-seconds at the pace of its first points ends at once
// rather than when the budget is spent.
void check_pace(int done, int total) {
  const double budget = run_budget().max_seconds, spent = seconds_since_start() - g_grid_start_s;
  if (budget <= 0 || done <= 0 || done >= total || (spent < 1.0 && 100.0 * done < total)) return;
  const double projected = g_grid_start_s + spent * total / done;
  if (projected > budget)
    end_run_over_budget(
        fmt::format("--max-seconds {}: the grid would take ~{:.0f} s ({} points, {} done in {:.1f} s); "
                    "raise --max-seconds or reduce --signal/--background N",
                    run_budget().max_seconds_text, projected, total, done, spent));
}

void report_progress(int done, int total) {
  if (g_progress) g_progress->update(done, total);
  check_pace(done, total);
}

// The schema key that starts with `prefix` (e.g. "evaluation.signal_min_"), or "".
std::string key_with_prefix(const ParamSchema& schema, const std::string& prefix) {
  for (const auto& p : schema.params)
    if (p.key.rfind(prefix, 0) == 0) return p.key;
  return "";
}

std::string key_with_suffix(const ParamSchema& schema, const std::string& suffix) {
  for (const auto& p : schema.params)
    if (p.key.size() >= suffix.size() && p.key.compare(p.key.size() - suffix.size(), suffix.size(), suffix) == 0)
      return p.key;
  return "";
}

void require_key(const std::string& key, const std::string& flag, const ParamSet& params, const std::string& what) {
  if (key.empty())
    throw UserError(fmt::format("{}: sensor {} has no {} parameter (see `rangesim show {}`)", flag, params.sensor_id(),
                                what, params.sensor_id()),
                    flag.substr(2));
}

void apply_grid(ParamSet& params, const ParamSchema& schema, const std::string& axis, const std::string& text) {
  const std::string flag = "--" + axis;
  const GridAxis g = parse_grid_axis(text, flag);
  const std::string lo = key_with_prefix(schema, "evaluation." + axis + "_min_");
  const std::string hi = key_with_prefix(schema, "evaluation." + axis + "_max_");
  require_key(lo, flag, params, "evaluation grid");
  params.set_real(lo, g.lo, flag, schema);
  params.set_real(hi, g.hi, flag, schema);
  params.set_integer("evaluation." + axis + "_points", g.n, flag, schema);
}

}  // namespace

ParamSet evaluate_params(const EvaluateOptions& opt) {
  ParamSet params = load_modelled_preset(opt.sensor, "evaluate", opt.settings);
  apply_evaluate_flags(params, opt);
  return params;
}

void apply_evaluate_flags(ParamSet& params, const EvaluateOptions& opt) {
  const ParamSchema& schema = schema_for(params.sensor_id(), params.origin());
  if (opt.samplings) {
    require_key(schema.find("multisampling.samplings") ? "multisampling.samplings" : "", "--samplings", params,
                "samplings");
    params.set_integer("multisampling.samplings", *opt.samplings, "--samplings", schema);
  }
  if (opt.adc_bits) {
    const std::string key = key_with_suffix(schema, ".adc_bits");
    require_key(key, "--adc-bits", params, "ADC bits");
    params.set_integer(key, *opt.adc_bits, "--adc-bits", schema);
  }
  if (opt.frames) {
    require_key(schema.find("evaluation.frames_averaged") ? "evaluation.frames_averaged" : "", "--frames", params,
                "frame-averaging");
    params.set_integer("evaluation.frames_averaged", *opt.frames, "--frames", schema);
  }
  if (opt.signal) apply_grid(params, schema, "signal", *opt.signal);
  if (opt.background) apply_grid(params, schema, "background", *opt.background);
  if (opt.signal && opt.signal_power)
    throw UserError("--signal and --signal-power both set the signal axis; give one", "signal-power");
  if (opt.background && opt.background_lux)
    throw UserError("--background and --background-lux both set the background axis; give one", "background-lux");
  if (!opt.scene.empty() && !opt.signal_power && !opt.background_lux)
    throw UserError("--scene sets the conditions of --background-lux / --signal-power; give one of them", "scene");
  if (opt.signal_power || opt.background_lux) {
    const PhysicalAxes a = physical_axes(params, physical_scene(opt.scene, params.sensor_id()), true);
    if (opt.signal_power) apply_physical_axis(params, "signal", *opt.signal_power, a.native_per_W, "--signal-power");
    if (opt.background_lux)
      apply_physical_axis(params, "background", *opt.background_lux, a.native_per_lux, "--background-lux");
  }
}

// summary.json's physical_axes: the scene, the conversion and the detectable ranges in lux and W
// (null when the axes are the sensor's own).
static nlohmann::json physical_axes_json(const EvaluateOptions& opt, const ParamSet& params, const golden::EvalResult& ev) {
  if (!opt.signal_power && !opt.background_lux) return nullptr;
  ParamSet p = params;
  const scene::Scene sc = physical_scene(opt.scene, params.sensor_id());
  const PhysicalAxes a = physical_axes(p, sc, false);
  nlohmann::json j = {{"scene", sc.file},
                      {"distance_m", a.distance_m},
                      {"radiometry", a.radiometry.conversion},
                      {"notes", a.notes}};
  const auto range = [](const golden::EvalRange& r, double per) {
    return nlohmann::json{{"lo", r.lo / per}, {"hi", r.hi / per}, {"at", r.at}};
  };
  if (opt.background_lux) {
    j["background"] = {{"unit", "lx"},
                       {"native_per_lux", a.native_per_lux},
                       {"native_unit", a.radiometry.unit},
                       {"lo", ev.background.values.front() / a.native_per_lux},
                       {"hi", ev.background.values.back() / a.native_per_lux}};
    j["background_range_lux"] = range(ev.background_range, a.native_per_lux);
  }
  if (opt.signal_power) {
    j["signal"] = {{"unit", "W"},
                   {"native_per_W", a.native_per_W},
                   {"native_unit", a.radiometry.unit},
                   {"lo", ev.signal.values.front() / a.native_per_W},
                   {"hi", ev.signal.values.back() / a.native_per_W}};
    j["signal_range_W"] = range(ev.signal_range, a.native_per_W);
  }
  return j;
}

ResourceEstimate evaluate_estimate(const ParamSet& params, bool monte_carlo) {
  // Measured on the shipped sensors: ~1 KiB a point for a kept grid with its Monte Carlo statistics
  // and output text; ~256 bytes a point of a block in flight; ~150 bytes a point in the files.
  const auto axis = [&](const char* key) { return params.has(key) ? static_cast<double>(params.integer(key)) : 1.0; };
  const double ns = axis("evaluation.signal_points"), nb = axis("evaluation.background_points");
  const double points = ns * nb, plotted = std::min(ns, 1001.0) * std::min(nb, 1001.0);
  ResourceEstimate e;
  e.memory_bytes =
      kBaseMemoryBytes + (monte_carlo ? points * 1200 : std::min(points, 65536 + ns) * 256) + plotted * 128;
  e.disk_bytes = points * (monte_carlo ? 400 : 160);
  e.what =
      fmt::format("{:.0f} x {:.0f} grid points{}", ns, nb,
                  monte_carlo ? " kept with their Monte Carlo statistics, ~1.2 KiB each" : ", streamed to the files");
  e.reduce = "the grid: --signal/--background LO:HI:N (or evaluation.signal_points, evaluation.background_points)";
  return e;
}

int run_evaluate(const EvaluateOptions& opt) {
  // Validate everything before computing or touching the output directory.
  const ParamSet params = evaluate_params(opt);
  const std::string dir = opt.out.empty() ? "rangesim-out/" + params.sensor_id() : opt.out;
  check_resources("evaluate", evaluate_estimate(params, false), dir);
  OutputDir out(dir, "--out", {"evaluate", opt.force});

  ProgressLine progress("evaluate", "operating points");
  g_progress = &progress;
  g_grid_start_s = seconds_since_start();
  // The grid goes to its files row by row: memory stays bounded for any grid.
  GridWriter grid(out);
  const golden::EvalResult ev = golden::evaluate_sensor_streamed(params, grid, &report_progress);
  g_progress = nullptr;
  const golden::EvalResult plotted = grid.finish(ev);
  const std::string plot_warning = opt.no_plots ? "" : render_plots(out, plotted);
  nlohmann::json summary = summary_json(ev, params);
  const nlohmann::json physical = physical_axes_json(opt, params, ev);
  if (!physical.is_null()) summary["physical_axes"] = physical;
  out.write("summary.json", summary.dump(2) + "\n");
  const std::vector<std::string> written = out.commit();
  summary["files"] = written;

  if (!plot_warning.empty()) fmt::print(stderr, "rangesim evaluate: warning: {}\n", plot_warning);
  if (opt.json) {
    fmt::print("{}\n", summary.dump(2));
    return 0;
  }
  fmt::print("{}\n", summary_text(ev));
  if (!physical.is_null()) {
    for (const auto& n : physical["notes"]) fmt::print(stderr, "rangesim evaluate: note: {}\n", n.get<std::string>());
    if (physical.contains("background_range_lux") && !(physical["background_range_lux"]["hi"].get<double>() > 0))
      fmt::print("detectable background: none at the grid's highest signal (detectable_area.csv has the map)\n");
    else if (physical.contains("background_range_lux"))
      fmt::print("detectable background: {:.4g} .. {:.4g} lx (at the grid's highest signal; {:.4g} {} per lx)\n",
                 physical["background_range_lux"]["lo"].get<double>(), physical["background_range_lux"]["hi"].get<double>(),
                 physical["background"]["native_per_lux"].get<double>(),
                 physical["background"]["native_unit"].get<std::string>());
    if (physical.contains("signal_range_W") && !(physical["signal_range_W"]["hi"].get<double>() > 0))
      fmt::print("detectable signal: none at the grid's lowest background (detectable_area.csv has the map)\n");
    else if (physical.contains("signal_range_W"))
      fmt::print("detectable signal: {:.4g} .. {:.4g} W of source power (at the grid's lowest background; {:.4g} {} per W)\n",
                 physical["signal_range_W"]["lo"].get<double>(), physical["signal_range_W"]["hi"].get<double>(),
                 physical["signal"]["native_per_W"].get<double>(), physical["signal"]["native_unit"].get<std::string>());
  }
  fmt::print("outputs in {}/: ", dir);
  for (size_t i = 0; i < written.size(); ++i)
    fmt::print("{}{}", i ? ", " : "", written[i].substr(written[i].find_last_of('/') + 1));
  fmt::print("\n");
  return 0;
}

}  // namespace rangesim::app
