// rangesim simulate ls-conventional: runs the clock-level model (bare kernels or SystemC) on a
// scene, reconstructs the range map by triangulation, compares it with the scene's exact ground
// truth and reports the measured frame timing beside golden::frame_timing.
#include <chrono>
#include <cmath>
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "app/cli_common.h"
#include "app/cmd_simulate.h"
#include "app/output_dir.h"
#include "app/simulate/simulate_output.h"
#include "app/simulate/simulate_report.h"
#include "app/simulate/trace_output.h"
#include "core/ls_conventional/config.h"
#include "core/preset.h"
#include "core/user_error.h"
#include "golden/ls_conventional/frame_timing.h"
#include "systemc/ls_conventional/scene_optics.h"
#include "scene/scene.h"
#include "systemc/ls_conventional/sensor.h"

namespace rangesim::app {

namespace {

using Clock = std::chrono::steady_clock;

struct Metrics {
  long long visible = 0, detected = 0, missed = 0, false_detections = 0;
};

int run_simulate_ls_conventional(const SimulateOptions& opt, const ParamSet& params) {
  const auto t_start = Clock::now();
  const LsConventionalConfig cfg = ls_conventional_from_params(params);
  if (cfg.comparator.adc_bits != 1)
    throw UserError(fmt::format("{}: comparator.adc_bits = {}: the clock-level model has the 1-bit comparator only; allowed: 1",
                                params.origin(), cfg.comparator.adc_bits));
  if (opt.scene.empty()) throw UserError("--scene is required: a scene file, e.g. scenes/plane.toml");
  const long long frames = opt.frames ? *opt.frames : cfg.timing.beam_positions;
  if (frames < 1 || frames > 1000000)
    throw UserError(fmt::format("--frames {}: allowed 1 <= N <= 1000000 (frame accesses; a range map is {})", frames,
                                cfg.timing.beam_positions));
  TraceOutput trace(opt.trace, opt.kernel_only);
  if (opt.tick && !opt.kernel_only)
    throw UserError("--tick selects the kernel's cycle-by-cycle path; use it with --kernel-only (SystemC always ticks)");

  const scene::Scene sc = scene::load_scene(opt.scene);
  const scene::SceneOptics optics(cfg, sc);
  OutputDir out(opt.out.empty() ? "rangesim-out/simulate/" + sc.name : opt.out, "--out");

  systemc::SensorKernelOptions kopt;
  kopt.event_skipping = !opt.tick;
  kopt.pixel.seed = opt.seed;
  kopt.pixel.sparse = !opt.dense;
  if (opt.noise_free) kopt.pixel.noise = systemc::PixelNoiseConfig::none();
  systemc::SensorRunOptions run;
  run.frames = frames;
  run.vcd_base = trace.vcd_base();
  for (int r : {0, cfg.pixel.rows / 4, cfg.pixel.rows / 2, cfg.pixel.rows - 1}) run.traced_rows.push_back(r);
  Progress progress("frame access", frames, t_start);
  run.progress = [&progress](long long done) { progress(done); };
  const systemc::StimulusSource source = [&optics](std::uint64_t f, systemc::FrameStimulus& s) { optics.stimulus(f, s); };
  const systemc::SensorRunResult res =
      opt.kernel_only ? systemc::run_sensor_kernel(cfg, kopt, source, run) : systemc::run_sensor_systemc(cfg, kopt, source, run);
  if (!res.errors.empty() || res.sc_errors > 0)
    throw std::runtime_error(fmt::format("the model reported {} error(s): {}", res.errors.size() + res.sc_errors,
                                         res.errors.empty() ? "see the SystemC messages above" : res.errors.front()));

  // ---- Range map and its error against the ground truth ----
  const golden::FrameTiming gt = golden::frame_timing(cfg.timing, cfg.multisampling.samplings);
  const int rows = cfg.pixel.rows;
  std::vector<std::vector<double>> map(static_cast<std::size_t>(rows), std::vector<double>(res.frames.size(), NAN));
  Metrics m;
  RangeErrorStats err;
  std::string points = "frame,beam_position,row,truth_visible,truth_centre_px,truth_range_m,detected,centre_px,range_m,error_px,error_m\n";
  std::string frames_csv = "frame,beam_position,cycles,end_cycle,reset,latch,search,address_stream,output,rows_detected\n";
  bool timing_matches = true;
  for (std::size_t f = 0; f < res.frames.size(); ++f) {
    const systemc::FrameResult& fr = res.frames[f];
    const int b = optics.beam_position(fr.frame);
    frames_csv += fmt::format("{},{},{},{}", fr.frame, b, fr.cycles, fr.end_cycle);
    for (std::size_t i = 0; i < fr.phase_cycles.size(); ++i) {
      frames_csv += fmt::format(",{}", fr.phase_cycles[i]);
      timing_matches = timing_matches && fr.phase_cycles[i] == gt.phases[i].cycles;
    }
    frames_csv += fmt::format(",{}\n", fr.rows_detected());
    for (int r = 0; r < rows; ++r) {
      const scene::RowTruth t = optics.truth(b, r);
      const systemc::CentreProcessorPins& p = fr.rows[static_cast<std::size_t>(r)];
      double range = NAN, err_px = NAN, err_m = NAN;
      if (p.valid) {
        range = optics.range_from_centre_m(b, p.centre_px());
        map[static_cast<std::size_t>(r)][f] = range;
      }
      if (t.visible) {
        ++m.visible;
        if (p.valid) {
          ++m.detected;
          err_px = p.centre_px() - t.centre_px;
          err_m = range - t.range_m;
          err.add(err_m, err_px);
        } else {
          ++m.missed;
        }
      } else if (p.valid) {
        ++m.false_detections;
      }
      if (t.visible || p.valid)
        points += fmt::format("{},{},{},{},{},{},{},{},{},{},{}\n", fr.frame, b, r, t.visible ? 1 : 0,
                              t.hit ? csv_number(t.centre_px) : "", t.hit ? csv_number(t.range_m) : "", p.valid ? 1 : 0,
                              p.valid ? csv_number(p.centre_px()) : "", csv_number(range), csv_number(err_px), csv_number(err_m));
    }
  }
  std::vector<std::string> beams;
  for (const auto& fr : res.frames) beams.push_back(fmt::format("b{}", optics.beam_position(fr.frame)));
  const std::string range_csv = range_map_csv(map, beams);

  // ---- Timing: measured from simulated time, beside the clock schedule ----
  const double frame_time_s = res.simulated_time_s / static_cast<double>(res.frames.size());
  const double frame_rate_Hz = 1.0 / frame_time_s;
  nlohmann::json phases = nlohmann::json::array();
  const systemc::FrameResult& first = res.frames.front();
  for (std::size_t i = 0; i < gt.phases.size(); ++i)
    phases.push_back({{"name", gt.phases[i].name},
                      {"cycles", first.phase_cycles[i]},
                      {"time_s", first.phase_cycles[i] / cfg.timing.clock_Hz},
                      {"golden_cycles", gt.phases[i].cycles}});
  nlohmann::json frame_cycles = nlohmann::json::array();
  for (const auto& fr : res.frames) frame_cycles.push_back(fr.cycles);
  const double wall_s = std::chrono::duration<double>(Clock::now() - t_start).count();
  nlohmann::json j = {
      {"sensor", params.sensor_id()},
      {"preset", params.origin()},
      {"scene", sc.name},
      {"scene_file", sc.file},
      {"target_shape", scene::shape_name(sc.shape)},
      {"harness", opt.kernel_only ? "kernel" : "systemc"},
      {"event_skipping", opt.kernel_only && !opt.tick},
      {"sparse", !opt.dense},
      {"noise", !opt.noise_free},
      {"seed", opt.seed},
      {"frames", static_cast<long long>(res.frames.size())},
      {"beam_positions", cfg.timing.beam_positions},
      {"samplings", cfg.multisampling.samplings},
      {"clock_Hz", cfg.timing.clock_Hz},
      {"cycles", res.cycles},
      {"frame_cycles", frame_cycles},
      {"simulated_time_s", res.simulated_time_s},
      {"frame_time_s", frame_time_s},
      {"frame_rate_Hz", frame_rate_Hz},
      {"range_maps_per_s", frame_rate_Hz / cfg.timing.beam_positions},
      {"phases", phases},
      {"golden",
       {{"frame_cycles", gt.frame_cycles},
        {"frame_time_s", gt.frame_time_s},
        {"frame_access_rate_Hz", gt.frame_access_rate_Hz},
        {"range_maps_per_s", gt.range_maps_per_s}}},
      {"timing_matches_golden", timing_matches},
      {"points_visible", m.visible},
      {"points_detected", m.detected},
      {"points_missed", m.missed},
      {"points_false", m.false_detections},
      {"pixels_simulated", res.pixels_simulated},
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
  if (!opt.no_plots)
    warning = render_range_map(out, map, fmt::format("{} — {} ({} frame accesses)", sc.name, params.sensor_id(), res.frames.size()),
                               "beam position (frame access)");
  SimulateSummary report;
  report.headline = fmt::format("{} on scene '{}' ({}): {} frame access{}, {}, {}", params.sensor_id(), sc.name,
                             scene::shape_name(sc.shape), res.frames.size(), res.frames.size() == 1 ? "" : "es",
                             opt.kernel_only ? "bare kernels" : "SystemC",
                             opt.noise_free ? "noise-free" : fmt::format("noise seed {}", opt.seed));
  report.phases = phases;
  report.frame_label = "frame access";
  report.frame_cycles = first.cycles, report.golden_frame_cycles = gt.frame_cycles;
  report.frame_time_s = frame_time_s, report.golden_frame_time_s = gt.frame_time_s;
  report.frame_rate_Hz = frame_rate_Hz, report.golden_frame_rate_Hz = gt.frame_access_rate_Hz;
  report.timing_matches = timing_matches;
  report.range_maps_per_s = frame_rate_Hz / cfg.timing.beam_positions, report.frames_per_range_map = cfg.timing.beam_positions;
  report.points_line = fmt::format("points visible {}, detected {}, missed {}, false {}", m.visible, m.detected, m.missed,
                                m.false_detections);
  report.error = err, report.error_in_px = true;
  report.wall_time_s = wall_s;
  report.wall_note = fmt::format("{:.3g} simulated cycles/s", res.cycles / res.wall_time_s);
  return finish_simulate(opt, out, trace, j, warning, report);
}

}  // namespace

const SimulateEntry& ls_conventional_simulate_entry() {
  static const SimulateEntry e{"ls-conventional", &run_simulate_ls_conventional, false, false};
  return e;
}

}  // namespace rangesim::app
