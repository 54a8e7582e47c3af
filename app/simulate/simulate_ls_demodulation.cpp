// rangesim simulate for ls-demodulation: runs the clock-level model (bare kernels or SystemC,
// systemc/ls_demodulation/) on a light-section scene with a modulated sheet beam over a strong
// background, reconstructs the range map by triangulation, compares it with the scene's exact
// ground truth and reports the measured frame timing beside golden::frame_timing_ls_demodulation.
// Scene format: docs/ls-demodulation-clock.md ("Scenes"); output files as for ls-conventional.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fmt/format.h>
#include <fstream>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <algorithm>

#include "app/cli_common.h"
#include "app/cmd_simulate.h"
#include "app/output_dir.h"
#include "app/simulate/simulate_output.h"
#include "app/simulate/simulate_report.h"
#include "app/simulate/trace_output.h"
#include "core/ls_demodulation/config.h"
#include "core/params.h"
#include "core/user_error.h"
#include "golden/common/evaluate_sensor.h"
#include "golden/common/frame_timing.h"
#include "scene/scene.h"
#include "systemc/ls_demodulation/sensor.h"
#include "golden/ls_demodulation/model.h"

namespace rangesim::app {

namespace {

using Clock = std::chrono::steady_clock;

// A light-section scene for ls-demodulation: a plane (optionally tilted row by row), a sheet beam
// stepping across the columns, a beam-on photocurrent at the spot peak and a uniform background.
struct DemodScene {
  std::string file;                // path as given
  std::string name;                // [scene].name
  std::string description;         // [scene].description
  double distance_m = 1.0;         // [target].distance_m: range of row 0
  double tilt_m_per_row = 0.0;     // [target].tilt_m_per_row: range change per row
  double signal_A = 1.11e-10;      // [beam].signal_A: beam-on photocurrent at the spot peak
  double first_column_px = 5.0;    // [beam].first_column_px: spot column of frame 0 at the preset's optics.distance_m
  double columns_per_frame = 1.0;  // [beam].columns_per_frame: beam step per frame, in pixels
  double background_A = 1e-7;      // [background].photocurrent_A: per pixel
  std::string shape = "plane";     // "plane" (tilted row by row) or "depth_map"
  std::vector<double> depth_map_m; // depth_map: depth of every pixel, row-major
  int map_columns = 0;             // depth_map: array columns
};

DemodScene load_demod_scene(const std::string& path, const LsDemodulationConfig& cfg) {
  const scene::Scene in = scene::load_scene(path, "ls-demodulation");
  DemodScene s;
  s.file = path;
  s.name = in.name;
  s.description = in.description;
  s.shape = scene::shape_name(in.shape);
  s.distance_m = in.distance_m;
  if (in.shape != scene::TargetShape::DepthMap && (s.distance_m < 0.05 || s.distance_m > 100))
    throw UserError(fmt::format("{}: target.distance_m = {:g}: allowed 0.05 <= value <= 100 m (ls-demodulation)", path, s.distance_m));
  s.tilt_m_per_row = in.get("target.tilt_m_per_row", 0.0);
  s.signal_A = in.get("beam.signal_A", 0.0);
  s.first_column_px = in.get("beam.first_column_px", 0.0);
  if (s.first_column_px > cfg.pixel.columns - 1.0)
    throw UserError(fmt::format("{}: beam.first_column_px = {:g}: allowed -1000 <= value <= {} (pixel.columns - 1)", path,
                                s.first_column_px, cfg.pixel.columns - 1));
  s.columns_per_frame = in.get("beam.columns_per_frame", 1.0);
  s.background_A = in.get("background.photocurrent_A", 0.0);
  const double z_last = s.distance_m + s.tilt_m_per_row * (cfg.pixel.rows - 1);
  if (z_last < 0.05)
    throw UserError(fmt::format("{}: target.tilt_m_per_row = {:g} puts the last row at {:g} m; allowed: every row >= 0.05 m",
                                path, s.tilt_m_per_row, z_last));
  if (in.shape == scene::TargetShape::DepthMap) {
    s.map_columns = cfg.pixel.columns;
    s.depth_map_m = in.depth_map->resample(cfg.pixel.rows, cfg.pixel.columns);
  }
  return s;
}

// Triangulation of the light-section geometry (thesis eq. 1.1): a target at range z images the
// sheet beam at disparity d(z) = f B / (p z) pixels; beam position b is aimed so that a target at
// the preset's optics.distance_m images at column x_b = first + b step.
struct DemodOptics {
  const LsDemodulationConfig& cfg;
  const DemodScene& sc;
  double disparity_px(double z) const { return cfg.optics.focal_length_m * cfg.optics.baseline_m / (cfg.pixel.pitch_m * z); }
  double beam_column(long long b) const { return sc.first_column_px + sc.columns_per_frame * static_cast<double>(b); }
  // Depth of the lit point on a row. Plane: the row's depth. Depth map: the first column (from
  // the left) where the stripe of the pixel's own depth lands on that pixel (bisection on the
  // bilinear depth profile); -1 when the beam misses the map on this row.
  double range_m(long long b, int row) const {
    if (sc.depth_map_m.empty()) return sc.distance_m + sc.tilt_m_per_row * row;
    using scene::row_depth_m;
    const int n = cfg.pixel.columns;
    const double* z = sc.depth_map_m.data() + static_cast<std::size_t>(row) * sc.map_columns;
    auto g = [&](double c) {
      return c - (beam_column(b) + disparity_px(row_depth_m(z, n, c)) - disparity_px(cfg.optics.distance_m));
    };
    const double c = scene::first_lit_column(n, g);
    return c < 0 ? -1 : row_depth_m(z, n, c);
  }
  double centre_px(long long b, int row) const {
    const double z = range_m(b, row);
    return z > 0 ? beam_column(b) + disparity_px(z) - disparity_px(cfg.optics.distance_m) : NAN;  // NaN: the beam misses
  }
  bool visible(long long b, int row) const {
    const double x = centre_px(b, row);
    return x >= 0 && x <= cfg.pixel.columns - 1;
  }
  double range_from_centre_m(long long b, double x) const {
    const double d = x - beam_column(b) + disparity_px(cfg.optics.distance_m);
    return d > 0 ? cfg.optics.focal_length_m * cfg.optics.baseline_m / (cfg.pixel.pitch_m * d) : NAN;
  }
  void stimulus(std::uint64_t f, systemc::DemodStimulus& s) const {
    const int R = cfg.pixel.rows, C = cfg.pixel.columns;
    const double sigma = cfg.spot.fwhm_px * cfg.spot.sigma_per_fwhm;
    s.beam_A.assign(static_cast<std::size_t>(R) * C, 0.0);
    s.background_A.assign(s.beam_A.size(), sc.background_A);
    for (int r = 0; r < R; ++r) {
      const double x0 = centre_px(static_cast<long long>(f), r);
      if (!std::isfinite(x0)) continue;  // no lit point on this row
      for (int c = 0; c < C; ++c)
        s.beam_A[static_cast<std::size_t>(r) * C + c] = sc.signal_A * std::exp(-(c - x0) * (c - x0) / (2 * sigma * sigma));
    }
  }
};

}  // namespace

namespace {
int run_simulate_ls_demodulation(const SimulateOptions& opt, const ParamSet& params) {
  const auto t_start = Clock::now();
  const LsDemodulationConfig cfg = ls_demodulation_from_params(params);
  if (cfg.comparator.adc_bits != 1)
    throw UserError(fmt::format("{}: comparator.adc_bits = {}: the clock-level model has the 1-bit comparator only; allowed: 1",
                                params.origin(), cfg.comparator.adc_bits));
  if (opt.scene.empty()) throw UserError("--scene is required: a scene file, e.g. scenes/ls-demodulation-plane.toml");
  TraceOutput trace(opt.trace, opt.kernel_only);
  const golden::FrameTiming gt = golden::frame_timing_ls_demodulation(params);
  const long long frames = opt.frames ? *opt.frames : gt.frames_per_range_map;
  if (frames < 1 || frames > 100000)
    throw UserError(fmt::format("--frames {}: allowed 1 <= N <= 100000 (frames; a range map is {})", frames,
                                gt.frames_per_range_map));
  const DemodScene sc = load_demod_scene(opt.scene, cfg);
  const DemodOptics optics{cfg, sc};
  OutputDir out(opt.out.empty() ? "rangesim-out/simulate/" + sc.name : opt.out, "--out");

  systemc::DemodKernelOptions kopt;
  kopt.event_skipping = !opt.tick;
  kopt.aggregate = !opt.tick && !opt.no_aggregate;  // ticking steps every period anyway
  kopt.seed = opt.seed;
  if (opt.noise_free) kopt.noise = systemc::DemodNoiseSwitches::none();
  const systemc::DemodStimulusSource source = [&optics](std::uint64_t f, systemc::DemodStimulus& s) { optics.stimulus(f, s); };
  Progress progress("frame", frames, t_start);
  const systemc::DemodProgress on_frame = [&progress](long long done) { progress(done); };
  systemc::DemodRunResult res;
  try {
    res = opt.kernel_only ? systemc::run_demod_kernel(cfg, kopt, source, frames, on_frame)
                          : systemc::run_demod_systemc(cfg, kopt, source, frames, trace.vcd_base(), on_frame);
  } catch (const std::invalid_argument& e) {
    throw UserError(fmt::format("{}: {}", params.origin(), e.what()));
  }
  if (res.sc_errors > 0) throw std::runtime_error(fmt::format("the model reported {} SystemC error(s)", res.sc_errors));
  if (static_cast<long long>(res.frames.size()) != frames)
    throw std::runtime_error(fmt::format("the simulation ended after {} of {} frames", res.frames.size(), frames));

  // ---- Range map and its error against the ground truth ----
  const int rows = cfg.pixel.rows;
  std::vector<std::vector<double>> map(static_cast<std::size_t>(rows), std::vector<double>(res.frames.size(), NAN));
  long long visible = 0, detected = 0, missed = 0, false_det = 0;
  RangeErrorStats err;
  std::string points = "frame,row,truth_visible,truth_centre_px,truth_range_m,detected,centre_px,range_m,error_px,error_m\n";
  std::string frames_csv = "frame,cycles,end_cycle";
  for (const auto& p : gt.phases) frames_csv += "," + p.name;
  frames_csv += ",rows_detected\n";
  bool timing_matches = true;
  for (std::size_t f = 0; f < res.frames.size(); ++f) {
    const auto& fr = res.frames[f];
    const auto b = static_cast<long long>(fr.frame);
    frames_csv += fmt::format("{},{},{}", fr.frame, fr.cycles, fr.end_cycle);
    for (std::size_t i = 0; i < fr.phase_cycles.size(); ++i) {
      frames_csv += fmt::format(",{}", fr.phase_cycles[i]);
      timing_matches = timing_matches && i < gt.phases.size() && fr.phase_cycles[i] == gt.phases[i].cycles;
    }
    timing_matches = timing_matches && fr.cycles == gt.frame_cycles;
    frames_csv += fmt::format(",{}\n", fr.rows_detected());
    for (int r = 0; r < rows; ++r) {
      const auto& rr = fr.rows[static_cast<std::size_t>(r)];
      const bool vis = optics.visible(b, r);
      const double truth_x = optics.centre_px(b, r), truth_z = optics.visible(b, r) || optics.range_m(b, r) > 0 ? optics.range_m(b, r) : NAN;
      double range = NAN, err_px = NAN, err_m = NAN;
      if (rr.valid()) {
        range = optics.range_from_centre_m(b, rr.centre_px());
        map[static_cast<std::size_t>(r)][f] = range;
      }
      if (vis) {
        ++visible;
        if (rr.valid() && std::isfinite(range)) {
          ++detected;
          err_px = rr.centre_px() - truth_x;
          err_m = range - truth_z;
          err.add(err_m, err_px);
        } else {
          ++missed;
        }
      } else if (rr.valid()) {
        ++false_det;
      }
      if (vis || rr.valid())
        points += fmt::format("{},{},{},{},{},{},{},{},{},{}\n", fr.frame, r, vis ? 1 : 0, csv_number(truth_x), csv_number(truth_z),
                              rr.valid() ? 1 : 0, rr.valid() ? csv_number(rr.centre_px()) : "", csv_number(range), csv_number(err_px), csv_number(err_m));
    }
  }
  std::vector<std::string> beams;
  for (const auto& fr : res.frames) beams.push_back(fmt::format("b{}", fr.frame));
  const std::string range_csv = range_map_csv(map, beams);

  // ---- Timing: measured from simulated time, beside the clock schedule ----
  const double frame_time_s = res.simulated_time_s / static_cast<double>(res.frames.size());
  const double frame_rate_Hz = 1.0 / frame_time_s;
  nlohmann::json phases = nlohmann::json::array();
  const auto& first = res.frames.front();
  for (std::size_t i = 0; i < gt.phases.size(); ++i)
    phases.push_back({{"name", gt.phases[i].name},
                      {"cycles", first.phase_cycles[i]},
                      {"time_s", first.phase_cycles[i] / cfg.readout.clock_Hz},
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
      {"aggregation", {{"requested", kopt.aggregate},
                       {"path", kopt.aggregate ? "aggregated" : "per_period"},
                       {"periods_per_window", cfg.correlator.cycles}}},
      {"noise", !opt.noise_free},
      {"seed", opt.seed},
      {"frames", static_cast<long long>(res.frames.size())},
      {"clock_Hz", cfg.readout.clock_Hz},
      {"cycles", res.cycles},
      {"simulated_time_s", res.simulated_time_s},
      {"frame_time_s", frame_time_s},
      {"frame_rate_Hz", frame_rate_Hz},
      {"range_maps_per_s", frame_rate_Hz / static_cast<double>(gt.frames_per_range_map)},
      {"phases", phases},
      {"golden",
       {{"frame_cycles", gt.frame_cycles},
        {"frame_time_s", gt.frame_time_s},
        {"frame_access_rate_Hz", gt.frame_access_rate_Hz},
        {"frames_per_range_map", gt.frames_per_range_map},
        {"range_maps_per_s", gt.range_maps_per_s}}},
      {"timing_matches_golden", timing_matches},
      {"points_visible", visible},
      {"points_detected", detected},
      {"points_missed", missed},
      {"points_false", false_det},
      {"wall_time_s", wall_s},
      {"simulation_wall_time_s", res.wall_time_s},
      {"simulated_cycles_per_s", res.cycles / res.wall_time_s},
      {"sc_errors", res.sc_errors},
  };
  err.to_json(j, true);
  out.write("range_map.csv", range_csv);
  out.write("points.csv", points);
  out.write("frames.csv", frames_csv);
  std::string warning;
  if (!opt.no_plots) warning = render_range_map(out, map, fmt::format("{} — {} ({} frames)", sc.name, params.sensor_id(), res.frames.size()),
                                                   "beam position (frame)");
  SimulateSummary report;
  report.headline = fmt::format("{} on scene '{}' ({}): {} frame{}, {}{}, {}", params.sensor_id(), sc.name, sc.shape, res.frames.size(),
                             res.frames.size() == 1 ? "" : "s", opt.kernel_only ? "bare kernels" : "SystemC",
                             opt.tick ? " (ticking)" : kopt.aggregate ? " (event skipping, periods aggregated)" : " (event skipping, period by period)",
                             opt.noise_free ? "noise-free" : fmt::format("noise seed {}", opt.seed));
  report.phases = phases;
  report.frame_label = "frame";
  report.frame_cycles = first.cycles, report.golden_frame_cycles = gt.frame_cycles;
  report.frame_time_s = frame_time_s, report.golden_frame_time_s = gt.frame_time_s;
  report.frame_rate_Hz = frame_rate_Hz, report.golden_frame_rate_Hz = gt.frame_access_rate_Hz;
  report.timing_matches = timing_matches;
  report.range_maps_per_s = frame_rate_Hz / static_cast<double>(gt.frames_per_range_map);
  report.frames_per_range_map = gt.frames_per_range_map;
  report.points_line = fmt::format("points visible {}, detected {}, missed {}, false {}", visible, detected, missed, false_det);
  report.error = err, report.error_in_px = true;
  report.wall_time_s = wall_s;
  report.wall_note = fmt::format("{:.3g} simulated cycles/s", res.cycles / res.wall_time_s);
  return finish_simulate(opt, out, trace, j, warning, report);
}

}  // namespace

const SimulateEntry& ls_demodulation_simulate_entry() {
  static const SimulateEntry e{"ls-demodulation", &run_simulate_ls_demodulation, true, false};
  return e;
}

}  // namespace rangesim::app
