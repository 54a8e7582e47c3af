// rangesim simulate for tof-spad: the clock-level model (systemc/tof_spad/, bare kernels or the
// sc_module) on a tof-spad scene (scenes/tof-spad-*.toml, read by scene/scene.h, checked here against the preset), the golden estimator on the
// measured histograms, the range error against the scene's ground truth and the measured frame
// timing beside golden::frame_timing_tof_spad. docs/tof-spad-clock.md.
//
// Default pixel subset (speed): the scene's [window] (default 4 rows x 16 columns around the
// array centre, i.e. 4 TDC groups per row); --dense simulates every pixel. Rows outside the
// subset still cost their cycles (the timing is always the whole array's).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <fstream>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include "app/cli_common.h"
#include "app/cmd_simulate.h"
#include "app/output_dir.h"
#include "app/simulate/simulate_output.h"
#include "app/simulate/simulate_report.h"
#include "app/simulate/trace_output.h"
#include "core/params.h"
#include "core/physics.h"
#include "core/tof_spad/config.h"
#include "core/user_error.h"
#include "golden/common/evaluate_sensor.h"
#include "scene/scene.h"
#include "systemc/tof_spad/sensor.h"
#include "golden/tof_spad/model.h"

namespace rangesim::app {

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;
using systemc::spad::PixelRates;

// A tof-spad scene: a plane or a step (two planes split at a column), SI units.
struct SpadScene {
  std::string file, name, description, shape;  // shape: "plane" or "step"
  double distance_m = 2.0;       // plane distance (step: columns < step_column)
  double step_distance_m = 3.0;  // step: columns >= step_column
  int step_column = 64;
  double signal_Hz = 1e5;             // PDE-weighted signal count rate per pixel at reference_distance_m
  double reference_distance_m = 2.0;  // signal falls as (reference / distance)^2
  double background_Hz = 1e5;         // ambient count rate per pixel
  int first_row = 62, rows = 4, first_column = 56, columns = 16;  // default simulated window
  int beam_first_row = 0, beam_rows = 0, beam_first_column = 0, beam_columns = 0;  // lit pixels (the echo's footprint)

  std::vector<double> depth_map_m;  // depth_map: depth of every pixel of the array, row-major
  int map_columns = 0;               // depth_map: array columns

  double distance_at(int row, int column) const {
    if (shape == "depth_map") return depth_map_m[static_cast<size_t>(row) * map_columns + column];
    return shape == "step" && column >= step_column ? step_distance_m : distance_m;
  }
  bool lit(int row, int column) const {
    return row >= beam_first_row && row < beam_first_row + beam_rows && column >= beam_first_column &&
           column < beam_first_column + beam_columns;
  }
  // Outside the beam's footprint a pixel receives background only (signal 0).
  PixelRates rates(int row, int column) const {
    const double d = distance_at(row, column);
    const double r = reference_distance_m / d;
    return {lit(row, column) ? signal_Hz * r * r : 0.0, background_Hz, 2 * d / phys::kSpeedOfLight_m_per_s};
  }
};

// A scene key that is checked against the preset here (the scene reader checks the generic range).
void check_range(const scene::Scene& s, const std::string& key, double lo, double hi, const std::string& unit) {
  if (!s.has(key)) return;
  const double v = s.get(key, 0);
  if (v < lo || v > hi)
    throw UserError(fmt::format("{}: {} = {:g}: allowed {:g} <= value <= {:g}{}", s.file, key, v, lo, hi, unit.empty() ? "" : " " + unit));
}

SpadScene load_spad_scene(const std::string& path, const TofSpadConfig& cfg, int array_rows, int array_columns) {
  const scene::Scene in = scene::load_scene(path, "tof-spad");
  SpadScene s;
  s.file = path;
  s.name = in.name;
  s.description = in.description;
  s.shape = scene::shape_name(in.shape);
  // Echo (with +-6 sigma of the pulse) inside the TDC range and the laser period.
  const double period_s = 1.0 / cfg.laser.repetition_rate_Hz;
  const double max_m = 0.5 * phys::kSpeedOfLight_m_per_s * (std::min(period_s, cfg.tdc.full_range_s) - 2e-9);
  check_range(in, "target.distance_m", 0.3, max_m, "m");
  check_range(in, "target.step_distance_m", 0.3, max_m, "m");
  check_range(in, "target.step_column", 0, array_columns, "");
  s.distance_m = in.distance_m;
  s.step_distance_m = in.get("target.step_distance_m", s.distance_m);
  s.step_column = static_cast<int>(in.get("target.step_column", array_columns / 2));
  if (in.shape == scene::TargetShape::DepthMap) {
    s.map_columns = array_columns;
    s.depth_map_m = in.depth_map->resample(array_rows, array_columns);
    for (double z : s.depth_map_m)
      if (z < 0.3 || z > max_m)
        throw UserError(fmt::format("{}: target.depth_map_file: distance {:g} m; allowed 0.3 <= distance <= {:g} m (laser period and "
                                    "TDC range)", path, z, max_m));
  }
  s.signal_Hz = in.get("rates.signal_Hz", s.signal_Hz);
  s.reference_distance_m = in.get("rates.reference_distance_m", s.distance_m);
  s.background_Hz = in.get("rates.background_Hz", s.background_Hz);
  auto get_int = [&](const std::string& key, int def, int lo, int hi) {
    check_range(in, key, lo, hi, "");
    return static_cast<int>(in.get(key, def));
  };
  const int cpt = cfg.tdc.columns_per_tdc;
  s.rows = get_int("window.rows", std::min(4, array_rows), 1, array_rows);
  s.first_row = get_int("window.first_row", (array_rows - s.rows) / 2, 0, array_rows - s.rows);
  s.columns = get_int("window.columns", std::min(16, array_columns), cpt, array_columns);
  if (s.columns % cpt != 0)
    throw UserError(fmt::format("{}: window.columns = {}: allowed a multiple of tdc.columns_per_tdc = {}", path, s.columns, cpt));
  s.beam_rows = get_int("beam.rows", array_rows, 1, array_rows);
  s.beam_first_row = get_int("beam.first_row", 0, 0, array_rows - s.beam_rows);
  s.beam_columns = get_int("beam.columns", array_columns, 1, array_columns);
  s.beam_first_column = get_int("beam.first_column", 0, 0, array_columns - s.beam_columns);
  const int default_first = ((array_columns - s.columns) / 2) / cpt * cpt;
  s.first_column = get_int("window.first_column", default_first, 0, array_columns - s.columns);
  if (s.first_column % cpt != 0)
    throw UserError(fmt::format("{}: window.first_column = {}: allowed a multiple of tdc.columns_per_tdc = {} (TDC group edge)",
                                path, s.first_column, cpt));
  return s;
}

}  // namespace

namespace {
int run_simulate_tof_spad(const SimulateOptions& opt, const ParamSet& params) {
  const auto t_start = Clock::now();
  const TofSpadConfig cfg = tof_spad_from_params(params);
  const int array_rows = static_cast<int>(params.integer("array.rows"));
  const int array_columns = static_cast<int>(params.integer("array.columns"));
  if (array_columns % cfg.tdc.columns_per_tdc != 0)
    throw UserError(fmt::format("{}: array.columns = {} is not a multiple of tdc.columns_per_tdc = {}", params.origin(),
                                array_columns, cfg.tdc.columns_per_tdc));
  if (opt.scene.empty()) throw UserError("--scene is required: a scene file, e.g. scenes/tof-spad-plane.toml");
  const long long frames = opt.frames ? *opt.frames : 1;
  if (frames < 1 || frames > 10000)
    throw UserError(fmt::format("--frames {}: allowed 1 <= N <= 10000 (tof-spad frames; a range map is {})", frames,
                                cfg.evaluation.frames_averaged));
  if (opt.tick && !opt.kernel_only)
    throw UserError("--tick / --no-event-skip selects the kernel's cycle-by-cycle TDC path; use it with --kernel-only");
  TraceOutput trace(opt.trace, opt.kernel_only);
  SpadScene sc = load_spad_scene(opt.scene, cfg, array_rows, array_columns);
  if (opt.dense) sc.first_row = 0, sc.rows = array_rows, sc.first_column = 0, sc.columns = array_columns;
  OutputDir out(opt.out.empty() ? "rangesim-out/simulate/" + sc.name : opt.out, "--out");

  systemc::spad::TofSpadKernelOptions kopt;
  kopt.seed = opt.seed;
  kopt.event_skipping = !opt.tick;  // per clock: every TDC cycle evaluated (identical histograms, tested)
  // Laser cycles drawn at once where they are independent (systemc/tof_spad/spad_aggregation.h); the
  // preset's dead time and afterpulses make them dependent, so its default run is per cycle.
  kopt.aggregate = !opt.tick && !opt.no_aggregate;
  // Sparse pixels: TDC groups outside the beam (background only) as one class, in closed form where
  // exact (spad_aggregation.h); --dense simulates every pixel of the array one by one.
  kopt.sparse = !opt.tick && !opt.dense;
  if (opt.noise_free) kopt.noise = systemc::spad::SpadNoise::none();
  const systemc::spad::TofSpadKernel kernel(cfg, array_rows, array_columns, kopt);
  systemc::spad::PixelSelection sel;
  for (int r = sc.first_row; r < sc.first_row + sc.rows; ++r) sel.rows.push_back(r);
  sel.first_group = sc.first_column / cfg.tdc.columns_per_tdc;
  sel.groups = sc.columns / cfg.tdc.columns_per_tdc;
  const systemc::spad::RateSource rates = [&sc](int r, int c) { return sc.rates(r, c); };

  const auto t_sim = Clock::now();
  const systemc::spad::SystemcRun res = opt.kernel_only
                                            ? systemc::spad::run_tof_spad_kernel(kernel, sel, rates, frames)
                                            : systemc::spad::run_tof_spad_systemc(kernel, sel, rates, frames, trace.vcd_base());
  const double sim_wall_s = std::chrono::duration<double>(Clock::now() - t_sim).count();
  if (res.sc_errors > 0)
    throw std::runtime_error(fmt::format("the model reported {} SystemC error(s): see the messages above", res.sc_errors));

  // ---- Range map and error against the ground truth ----
  const golden::FrameTiming gt = golden::frame_timing_tof_spad(params);
  std::vector<std::vector<double>> sum(static_cast<size_t>(sc.rows), std::vector<double>(static_cast<size_t>(sc.columns), 0.0));
  std::vector<std::vector<int>> cnt(static_cast<size_t>(sc.rows), std::vector<int>(static_cast<size_t>(sc.columns), 0));
  long long points_total = 0, detected = 0, photons = 0, avalanches = 0, groups_agg = 0, groups_cyc = 0;
  long long groups_bg = 0, groups_bg_cyc = 0, background_points = 0, background_detections = 0;
  RangeErrorStats err_stats;
  bool timing_matches = true;
  std::string points = "frame,row,column,truth_range_m,detected,range_m,error_m,events\n";
  std::string frames_csv = "frame,cycles,laser_cycles,histogram_readout,avalanches,photons\n";
  for (const auto& f : res.frames) {
    frames_csv += fmt::format("{},{},{},{},{},{}\n", f.frame, f.cycles, f.phase_cycles[0], f.phase_cycles[1], f.avalanches, f.photons);
    timing_matches = timing_matches && f.cycles == gt.frame_cycles && f.phase_cycles[0] == gt.phases[0].cycles &&
                     f.phase_cycles[1] == gt.phases[1].cycles;
    photons += f.photons, avalanches += f.avalanches;
    groups_agg += f.groups_aggregated, groups_cyc += f.groups_per_cycle;
    groups_bg += f.groups_background, groups_bg_cyc += f.groups_background_per_cycle;
    for (const auto& p : f.pixels) {
      const double truth = sc.distance_at(p.row, p.column);
      long long ev = 0;
      for (long long e : p.events) ev += e;
      ++points_total;
      double err = NAN;
      const bool lit = sc.lit(p.row, p.column);
      background_points += !lit;
      if (p.time_s && !lit) ++background_detections;  // a spurious peak: no echo to range (no error)
      if (p.time_s) {
        ++detected;
        if (lit) err = p.range_m - truth, err_stats.add(err);
        const auto r = static_cast<size_t>(p.row - sc.first_row), c = static_cast<size_t>(p.column - sc.first_column);
        sum[r][c] += p.range_m, ++cnt[r][c];
      }
      points += fmt::format("{},{},{},{},{},{},{},{}\n", f.frame, p.row, p.column, csv_number(truth), p.time_s ? 1 : 0,
                            p.time_s ? csv_number(p.range_m) : "", csv_number(err), ev);
    }
  }
  std::vector<std::vector<double>> map(static_cast<size_t>(sc.rows), std::vector<double>(static_cast<size_t>(sc.columns), NAN));
  std::string range_csv = "row";
  for (int c = 0; c < sc.columns; ++c) range_csv += fmt::format(",c{}", sc.first_column + c);
  range_csv += "\n";
  for (int r = 0; r < sc.rows; ++r) {
    range_csv += std::to_string(sc.first_row + r);
    for (int c = 0; c < sc.columns; ++c) {
      const auto ur = static_cast<size_t>(r), uc = static_cast<size_t>(c);
      if (cnt[ur][uc]) map[ur][uc] = sum[ur][uc] / cnt[ur][uc];
      range_csv += "," + csv_number(map[ur][uc]);
    }
    range_csv += "\n";
  }

  // ---- Timing: measured from simulated time, beside the clock schedule ----
  const double frame_time_s = res.simulated_time_s / static_cast<double>(res.frames.size());
  const double frame_rate_Hz = 1.0 / frame_time_s;
  nlohmann::json phases = nlohmann::json::array();
  const auto& first = res.frames.front();
  for (size_t i = 0; i < gt.phases.size(); ++i)
    phases.push_back({{"name", gt.phases[i].name},
                      {"cycles", first.phase_cycles[i]},
                      {"time_s", first.phase_cycles[i] / kernel.clock_Hz()},
                      {"golden_cycles", gt.phases[i].cycles}});
  const double wall_s = std::chrono::duration<double>(Clock::now() - t_start).count();
  nlohmann::json j = {
      {"sensor", params.sensor_id()},
      {"preset", params.origin()},
      {"scene", sc.name},
      {"scene_file", sc.file},
      {"target_shape", sc.shape},
      {"harness", opt.kernel_only ? "kernel" : "systemc"},
      {"event_skipping", !opt.tick},
      {"sparse", !opt.dense},
      {"window", {{"first_row", sc.first_row}, {"rows", sc.rows}, {"first_column", sc.first_column}, {"columns", sc.columns}}},
      {"beam", {{"first_row", sc.beam_first_row}, {"rows", sc.beam_rows}, {"first_column", sc.beam_first_column}, {"columns", sc.beam_columns}}},
      {"noise", !opt.noise_free},
      {"seed", opt.seed},
      {"frames", static_cast<long long>(res.frames.size())},
      {"clock_Hz", kernel.clock_Hz()},
      {"cycles", res.measured_cycles},
      {"simulated_time_s", res.simulated_time_s},
      {"frame_time_s", frame_time_s},
      {"frame_rate_Hz", frame_rate_Hz},
      {"range_maps_per_s", frame_rate_Hz / static_cast<double>(gt.frames_per_range_map)},
      {"phases", phases},
      {"golden",
       {{"frame_cycles", gt.frame_cycles},
        {"frame_time_s", gt.frame_time_s},
        {"frame_access_rate_Hz", gt.frame_access_rate_Hz},
        {"range_maps_per_s", gt.range_maps_per_s}}},
      {"timing_matches_golden", timing_matches},
      {"points", points_total},
      {"points_detected", detected},
      {"pixels_simulated", sc.rows * sc.columns},
      {"photons_simulated", photons},
      {"avalanches_simulated", avalanches},
      {"wall_time_s", wall_s},
      {"simulation_wall_time_s", sim_wall_s},
      {"photons_per_s", static_cast<double>(photons) / sim_wall_s},
      {"sc_errors", res.sc_errors},
      {"aggregation",
       {{"requested", kopt.aggregate},
        {"path", groups_agg == 0 ? "per_cycle" : groups_cyc == 0 ? "aggregated" : "mixed"},
        {"groups_aggregated", groups_agg},
        {"groups_per_cycle", groups_cyc},
        {"blocker", kernel.aggregation_blocker()}}},
      {"background_only",
       {{"points", background_points},
        {"detections", background_detections},
        {"groups_class", groups_bg},
        {"groups_per_cycle", groups_bg_cyc},
        {"blocker", kernel.background_blocker()}}},
  };
  err_stats.to_json(j, false);
  out.write("range_map.csv", range_csv);
  out.write("points.csv", points);
  out.write("frames.csv", frames_csv);
  std::string warning;
  if (!opt.no_plots) warning = render_range_map(out, map, fmt::format("{} — tof-spad ({} frame{})", sc.name, res.frames.size(), res.frames.size() == 1 ? "" : "s"),
                                                   "column in window", "row in window");
  SimulateSummary report;
  report.headline = fmt::format("tof-spad on scene '{}' ({}): {} frame{}, {}, {}, window {} rows x {} columns", sc.name, sc.shape,
                             res.frames.size(), res.frames.size() == 1 ? "" : "s", opt.kernel_only ? "bare kernels" : "SystemC",
                             opt.noise_free ? "noise-free" : fmt::format("noise seed {}", opt.seed), sc.rows, sc.columns);
  report.phases = phases;
  report.frame_label = "frame";
  report.frame_cycles = first.cycles, report.golden_frame_cycles = gt.frame_cycles;
  report.frame_time_s = frame_time_s, report.golden_frame_time_s = gt.frame_time_s;
  report.frame_rate_Hz = frame_rate_Hz, report.golden_frame_rate_Hz = gt.frame_access_rate_Hz;
  report.timing_matches = timing_matches;
  report.range_maps_per_s = frame_rate_Hz / static_cast<double>(gt.frames_per_range_map);
  report.frames_per_range_map = gt.frames_per_range_map;
  report.points_line = fmt::format("pixels {} x {} frames, detected {}", sc.rows * sc.columns, res.frames.size(), detected);
  if (background_points > 0)
    report.points_line += fmt::format(" ({} of {} background-only points: spurious, not in the error)", background_detections, background_points);
  report.error = err_stats;
  report.wall_time_s = wall_s;
  report.wall_note = fmt::format("{:.3g} photons/s simulated; laser cycles: {} group rows aggregated, {} per cycle{}",
                                 static_cast<double>(photons) / sim_wall_s, groups_agg, groups_cyc,
                                 kopt.aggregate && !kernel.aggregation_blocker().empty() ? " (" + kernel.aggregation_blocker() + ")" : "");
  if (groups_bg + groups_bg_cyc > 0)
    report.wall_note += fmt::format("; background-only group rows: {} as a class, {} per cycle{}", groups_bg, groups_bg_cyc,
                                    groups_bg_cyc > 0 && !kernel.background_blocker().empty() ? " (" + kernel.background_blocker() + ")" : "");
  return finish_simulate(opt, out, trace, j, warning, report);
}

}  // namespace

const SimulateEntry& tof_spad_simulate_entry() {
  static const SimulateEntry e{"tof-spad", &run_simulate_tof_spad, true, false};
  return e;
}

}  // namespace rangesim::app
