// rangesim evaluate: the thesis's background-light and range-accuracy evaluation over a
// log-spaced signal x background grid, written as CSV maps, summary.json and heat maps.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <fmt/format.h>
#include <nlohmann/json.hpp>
#include <sstream>
#include <unistd.h>

#include "app/cli_common.h"
#include "app/commands.h"
#include "app/output_dir.h"
#include "app/plot.h"
#include "core/ls_conventional_config.h"
#include "core/preset.h"
#include "golden/frame_timing.h"
#include "golden/ls_conventional_eval.h"

namespace rangesim::app {

nlohmann::json frame_timing_json(const golden::FrameTiming& t, const FrameTimingConfig& cfg);

namespace {

using Clock = std::chrono::steady_clock;
Clock::time_point g_start;

// Progress on stderr once a run has taken more than a second: a live line on a terminal,
// a line per quarter otherwise (CI logs).
void report_progress(int done, int total) {
  const double elapsed = std::chrono::duration<double>(Clock::now() - g_start).count();
  if (elapsed < 1.0 && done < total) return;
  static int last_quarter = -1;
  if (isatty(fileno(stderr))) {
    std::fprintf(stderr, "\revaluate: %d/%d operating points, %.1f s%s", done, total, elapsed, done == total ? "\n" : "");
  } else if (int q = 4 * done / std::max(total, 1); q != last_quarter) {
    last_quarter = q;
    std::fprintf(stderr, "evaluate: %d/%d operating points, %.1f s\n", done, total, elapsed);
  }
}

double nan_to_null_safe(double v) { return std::isfinite(v) ? v : 0.0; }

std::string matrix_csv(const golden::Evaluation& ev, const std::function<std::string(const golden::OperatingPoint&)>& cell) {
  std::ostringstream o;
  o << "background_V\\signal_V";
  for (double s : ev.signal_V) o << fmt::format(",{:.6g}", s);
  o << "\n";
  for (size_t ib = 0; ib < ev.background_V.size(); ++ib) {
    o << fmt::format("{:.6g}", ev.background_V[ib]);
    for (size_t is = 0; is < ev.signal_V.size(); ++is) o << "," << cell(ev.at(ib, is));
    o << "\n";
  }
  return o.str();
}

std::string points_csv(const golden::Evaluation& ev) {
  std::ostringstream o;
  o << "signal_V,background_V,detect,sbr_total_dB,sbr_ratio_dB,quantisation_rms_px,resolution_px,"
       "worst_error_px,noise_std_px,accuracy_px,accuracy_m,p_detect\n";
  for (const auto& p : ev.points) {
    const bool ok = p.detect == golden::Detect::Detectable;
    auto num = [&](double v) { return ok ? fmt::format("{:.6g}", v) : std::string(); };
    o << fmt::format("{:.6g},{:.6g},{},{:.4f},{:.4f},{},{},{},{},{},{},{}\n", p.signal_V, p.background_V,
                     golden::to_string(p.detect), p.sbr_total_dB, p.sbr_ratio_dB, num(p.quantisation_rms_px),
                     num(p.resolution_px), num(p.worst_error_px), num(p.noise_std_px), num(p.accuracy_px),
                     num(p.accuracy_m), num(p.p_detect));
  }
  return o.str();
}

nlohmann::json summary_json(const golden::Evaluation& ev, const LsConventionalConfig& cfg, const ParamSet& params,
                            const golden::FrameTiming& timing) {
  const auto& s = ev.summary;
  nlohmann::json j;
  j["sensor"] = params.sensor_id();
  j["preset"] = params.origin();
  j["samplings"] = s.samplings;
  j["adc_bits"] = s.adc_bits;
  j["grid"] = {{"signal_min_V", ev.signal_V.front()},         {"signal_max_V", ev.signal_V.back()},
               {"signal_points", ev.signal_V.size()},          {"background_min_V", ev.background_V.front()},
               {"background_max_V", ev.background_V.back()}, {"background_points", ev.background_V.size()}};
  j["points_total"] = s.points_total;
  j["points_detectable"] = s.points_detectable;
  j["signal_range_dB"] = s.signal.range_dB;
  j["signal_min_V"] = s.signal.lo_V;
  j["signal_max_V"] = s.signal.hi_V;
  j["signal_max_limited_by_grid"] = s.signal.hi_limited_by_grid;
  j["signal_range_at_background_V"] = ev.background_V.front();
  j["background_range_dB"] = s.background.range_dB;
  j["background_min_V"] = s.background.lo_V;
  j["background_max_V"] = s.background.hi_V;
  j["background_max_limited_by_grid"] = s.background.hi_limited_by_grid;
  j["background_range_at_signal_V"] = ev.signal_V.back();
  j["sbr_min_dB"] = nan_to_null_safe(s.sbr_min_dB);
  j["sbr_max_dB"] = nan_to_null_safe(s.sbr_max_dB);
  j["sbr_ratio_min_dB"] = nan_to_null_safe(s.sbr_ratio_min_dB);
  j["sbr_ratio_max_dB"] = nan_to_null_safe(s.sbr_ratio_max_dB);
  j["accuracy_min_px"] = s.accuracy_min_px;
  j["accuracy_max_px"] = s.accuracy_max_px;
  j["accuracy_min_m"] = s.accuracy_min_m;
  j["accuracy_max_m"] = s.accuracy_max_m;
  j["range_per_px_m"] = s.range_per_px_m;
  j["distance_m"] = cfg.optics.distance_m;
  j["frame_access_rate_Hz"] = timing.frame_access_rate_Hz;
  j["range_maps_per_s"] = timing.range_maps_per_s;
  j["frame_time_s"] = timing.frame_time_s;
  return j;
}

void print_summary(const golden::Evaluation& ev, const LsConventionalConfig& cfg, const std::string& sensor,
                   const golden::FrameTiming& t) {
  const auto& s = ev.summary;
  fmt::print("{} evaluation: {} sampling{}, {}-bit, grid {} x {} (signal {:g}-{:g} V, background {:g}-{:g} V)\n\n",
             sensor, s.samplings, s.samplings == 1 ? "" : "s", s.adc_bits, ev.signal_V.size(), ev.background_V.size(),
             ev.signal_V.front(), ev.signal_V.back(), ev.background_V.front(), ev.background_V.back());
  fmt::print("  {:<34} {} / {}\n", "detectable points", s.points_detectable, s.points_total);
  if (s.points_detectable == 0) {
    fmt::print("  nothing is detectable on this grid: see detectable_area.csv for the reason at each point\n");
  } else {
    fmt::print("  {:<34} {:.2f} dB  ({:.4g} .. {:.4g} V at background {:.4g} V{})\n", "signal range", s.signal.range_dB,
               s.signal.lo_V, s.signal.hi_V, ev.background_V.front(), s.signal.hi_limited_by_grid ? "; upper edge = grid end" : "");
    fmt::print("  {:<34} {:.2f} dB  ({:.4g} .. {:.4g} V at signal {:.4g} V{})\n", "background range", s.background.range_dB,
               s.background.lo_V, s.background.hi_V, ev.signal_V.back(), s.background.hi_limited_by_grid ? "; upper edge = grid end" : "");
    fmt::print("  {:<34} {:.2f} .. {:.2f} dB\n", "SBR' eq. 3.11 (V_sig+V_bg)/V_bg", s.sbr_min_dB, s.sbr_max_dB);
    fmt::print("  {:<34} {:.2f} .. {:.2f} dB\n", "SBR' eq. 3.23 V_sig/V_bg", s.sbr_ratio_min_dB, s.sbr_ratio_max_dB);
    fmt::print("  {:<34} {:.4f} .. {:.4f} px  ({:.3f} .. {:.3f} mm at {:g} m)\n", "range accuracy (rms)", s.accuracy_min_px,
               s.accuracy_max_px, s.accuracy_min_m * 1e3, s.accuracy_max_m * 1e3, cfg.optics.distance_m);
  }
  fmt::print("  {:<34} {:.2f} kHz  ({:.1f} range maps/s)\n", "frame access rate", t.frame_access_rate_Hz / 1e3,
             t.range_maps_per_s);
}

}  // namespace

int run_evaluate(const EvaluateOptions& opt) {
  // Validate everything before computing or touching the output directory.
  ParamSet params = load_modelled_preset(opt.sensor, "evaluate");
  const ParamSchema& schema = schema_for(params.sensor_id(), params.origin());
  if (opt.samplings) params.set_integer("multisampling.samplings", *opt.samplings, "--samplings", schema);
  if (opt.adc_bits) params.set_integer("comparator.adc_bits", *opt.adc_bits, "--adc-bits", schema);
  LsConventionalConfig cfg = ls_conventional_from_params(params);
  if (opt.signal) {
    const GridAxis g = parse_grid_axis(*opt.signal, "--signal");
    cfg.grid.signal_min_V = g.lo, cfg.grid.signal_max_V = g.hi, cfg.grid.signal_points = g.n;
  }
  if (opt.background) {
    const GridAxis g = parse_grid_axis(*opt.background, "--background");
    cfg.grid.background_min_V = g.lo, cfg.grid.background_max_V = g.hi, cfg.grid.background_points = g.n;
  }
  const std::string dir = opt.out.empty() ? "rangesim-out/" + params.sensor_id() : opt.out;
  OutputDir out(dir, "--out");

  g_start = Clock::now();
  const golden::Evaluation ev = golden::evaluate(cfg, &report_progress);
  const golden::FrameTiming timing = golden::frame_timing(cfg.timing, cfg.multisampling.samplings);

  out.write("points.csv", points_csv(ev));
  out.write("detectable_area.csv", matrix_csv(ev, [](const auto& p) { return std::string(golden::to_string(p.detect)); }));
  out.write("accuracy_px.csv", matrix_csv(ev, [](const auto& p) {
              return p.detect == golden::Detect::Detectable ? fmt::format("{:.6g}", p.accuracy_px) : std::string();
            }));
  out.write("accuracy_mm.csv", matrix_csv(ev, [](const auto& p) {
              return p.detect == golden::Detect::Detectable ? fmt::format("{:.6g}", p.accuracy_m * 1e3) : std::string();
            }));
  std::string plot_warning;
  if (!opt.no_plots)
    plot_warning = render_heatmaps(out, ev, fmt::format("{} ({} samplings)", params.sensor_id(), cfg.multisampling.samplings));
  nlohmann::json summary = summary_json(ev, cfg, params, timing);
  summary["frame_timing"] = frame_timing_json(timing, cfg.timing);
  out.write("summary.json", summary.dump(2) + "\n");
  const std::vector<std::string> written = out.commit();
  summary["files"] = written;

  if (!plot_warning.empty()) fmt::print(stderr, "rangesim evaluate: warning: {}\n", plot_warning);
  if (opt.json) {
    fmt::print("{}\n", summary.dump(2));
  } else {
    print_summary(ev, cfg, params.sensor_id(), timing);
    fmt::print("\noutputs in {}/: ", dir);
    for (size_t i = 0; i < written.size(); ++i)
      fmt::print("{}{}", i ? ", " : "", written[i].substr(written[i].find_last_of('/') + 1));
    fmt::print("\n");
  }
  return 0;
}

}  // namespace rangesim::app
