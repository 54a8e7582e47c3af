// rangesim simulate: runs the clock-level ls-conventional model (bare kernels or SystemC) on a
// scene, reconstructs the range map by triangulation, compares it with the scene's exact ground
// truth and reports the measured frame timing beside golden::frame_timing.
#include "app/cmd_simulate.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include "app/cli_common.h"
#include "app/output_dir.h"
#include "app/simulate/simulate_output.h"
#include "core/ls_conventional_config.h"
#include "core/preset.h"
#include "core/user_error.h"
#include "golden/frame_timing.h"
#include "scene/optics.h"
#include "scene/scene.h"
#include "systemc/ls_conventional_sensor.h"

// libsystemc.so defines main() and refers to sc_main; rangesim has its own main(), so this
// definition only satisfies the linker and is never called. (Test binaries that link SystemC
// define their own sc_main and do not link this file.)
extern "C" int sc_main(int, char*[]) { return 1; }

namespace rangesim::app {

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

struct Metrics {
  long long visible = 0, detected = 0, missed = 0, false_detections = 0;
  double sum_sq_m = 0, sum_sq_px = 0, sum_m = 0, max_abs_m = 0;
  double rms_m() const { return detected ? std::sqrt(sum_sq_m / detected) : NAN; }
  double rms_px() const { return detected ? std::sqrt(sum_sq_px / detected) : NAN; }
  double mean_m() const { return detected ? sum_m / detected : NAN; }
};

}  // namespace

int run_simulate(const SimulateOptions& opt) {
  const auto t_start = Clock::now();
  ParamSet params = load_modelled_preset(opt.sensor, "simulate");
  if (opt.no_aggregate && params.sensor_id() != "tof-lockin")
    throw UserError(fmt::format("--no-aggregate: {} has no aggregated path to switch off; allowed with tof-lockin",
                                params.sensor_id()));
  if (params.sensor_id() == "ls-demodulation") return run_simulate_ls_demodulation(opt, params);
  if (params.sensor_id() == "tof-lockin") return run_simulate_tof_lockin(opt, params);
  if (params.sensor_id() == "tof-spad") return run_simulate_tof_spad(opt, params);
  const LsConventionalConfig cfg = ls_conventional_from_params(params);
  if (cfg.comparator.adc_bits != 1)
    throw UserError(fmt::format("{}: comparator.adc_bits = {}: the clock-level model has the 1-bit comparator only; allowed: 1",
                                params.origin(), cfg.comparator.adc_bits));
  if (opt.scene.empty()) throw UserError("--scene is required: a scene file, e.g. scenes/plane.toml");
  const long long frames = opt.frames ? *opt.frames : cfg.timing.beam_positions;
  if (frames < 1 || frames > 1000000)
    throw UserError(fmt::format("--frames {}: allowed 1 <= N <= 1000000 (frame accesses; a range map is {})", frames,
                                cfg.timing.beam_positions));
  if (!opt.trace.empty()) {
    if (opt.kernel_only)
      throw UserError("--trace needs the SystemC model; drop --kernel-only (the bare kernels have no waveform)");
    if (opt.trace.size() < 5 || opt.trace.substr(opt.trace.size() - 4) != ".vcd")
      throw UserError(fmt::format("--trace {}: the waveform file name must end in .vcd", opt.trace));
    const fs::path parent = fs::absolute(opt.trace).parent_path();
    if (!fs::is_directory(parent) || ::access(parent.c_str(), W_OK) != 0)
      throw UserError(fmt::format("--trace {}: directory {} does not exist or is not writable", opt.trace, parent.string()));
  }
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
  // Waveform: written beside the target under a temporary name, renamed when the run succeeded.
  const std::string vcd_tmp_base = opt.trace.empty() ? "" : fmt::format("{}.partial-{}", opt.trace, ::getpid());
  run.vcd_base = vcd_tmp_base;
  for (int r : {0, cfg.pixel.rows / 4, cfg.pixel.rows / 2, cfg.pixel.rows - 1}) run.traced_rows.push_back(r);
  auto last_report = Clock::now();
  run.progress = [&](long long done) {
    const auto now = Clock::now();
    const double elapsed = std::chrono::duration<double>(now - t_start).count();
    if (elapsed > 2.0 && (std::chrono::duration<double>(now - last_report).count() > 1.0 || done == frames)) {
      fmt::print(stderr, "simulate: frame access {}/{} ({:.0f}%), {:.1f} s\n", done, frames, 100.0 * done / frames, elapsed);
      last_report = now;
    }
  };
  const systemc::StimulusSource source = [&optics](std::uint64_t f, systemc::FrameStimulus& s) { optics.stimulus(f, s); };
  systemc::SensorRunResult res;
  try {
    res = opt.kernel_only ? systemc::run_sensor_kernel(cfg, kopt, source, run) : systemc::run_sensor_systemc(cfg, kopt, source, run);
  } catch (...) {
    if (!vcd_tmp_base.empty()) std::remove((vcd_tmp_base + ".vcd").c_str());
    throw;
  }
  if (!res.errors.empty() || res.sc_errors > 0) {
    if (!vcd_tmp_base.empty()) std::remove((vcd_tmp_base + ".vcd").c_str());
    throw std::runtime_error(fmt::format("the model reported {} error(s): {}", res.errors.size() + res.sc_errors,
                                         res.errors.empty() ? "see the SystemC messages above" : res.errors.front()));
  }

  // ---- Range map and its error against the ground truth ----
  const golden::FrameTiming gt = golden::frame_timing(cfg.timing, cfg.multisampling.samplings);
  const int rows = cfg.pixel.rows;
  std::vector<std::vector<double>> map(static_cast<std::size_t>(rows), std::vector<double>(res.frames.size(), NAN));
  Metrics m;
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
          m.sum_sq_px += err_px * err_px;
          m.sum_sq_m += err_m * err_m;
          m.sum_m += err_m;
          m.max_abs_m = std::max(m.max_abs_m, std::fabs(err_m));
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
      {"range_error_rms_m", json_number(m.rms_m())},
      {"range_error_rms_px", json_number(m.rms_px())},
      {"range_error_mean_m", json_number(m.mean_m())},
      {"range_error_max_abs_m", m.detected ? nlohmann::json(m.max_abs_m) : nlohmann::json(nullptr)},
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

  out.write("range_map.csv", range_csv);
  out.write("points.csv", points);
  out.write("frames.csv", frames_csv);
  std::string warning;
  if (!opt.no_plots)
    warning = render_range_map(out, map, fmt::format("{} — {} ({} frame accesses)", sc.name, params.sensor_id(), res.frames.size()),
                               "beam position (frame access)");
  if (!warning.empty()) j["warnings"] = {warning};
  out.write("summary.json", j.dump(2) + "\n");
  const std::vector<std::string> written = out.commit();
  if (!vcd_tmp_base.empty()) fs::rename(vcd_tmp_base + ".vcd", opt.trace);

  if (opt.json) {
    fmt::print("{}\n", j.dump(2));
    return kExitOk;
  }
  if (!warning.empty()) fmt::print(stderr, "rangesim: warning: {}\n", warning);
  fmt::print("{} on scene '{}' ({}): {} frame access{}, {}, {}\n\n", params.sensor_id(), sc.name, scene::shape_name(sc.shape),
             res.frames.size(), res.frames.size() == 1 ? "" : "es", opt.kernel_only ? "bare kernels" : "SystemC",
             opt.noise_free ? "noise-free" : fmt::format("noise seed {}", opt.seed));
  fmt::print("  {:<16} {:>8} {:>8} {:>11}\n", "phase", "cycles", "golden", "time");
  for (const auto& p : phases)
    fmt::print("  {:<16} {:>8} {:>8} {:>8.2f} ns\n", p["name"].get<std::string>(), p["cycles"].get<long long>(),
               p["golden_cycles"].get<long long>(), p["time_s"].get<double>() * 1e9);
  fmt::print("  {:<16} {:>8} {:>8}\n\n", "frame access", first.cycles, gt.frame_cycles);
  fmt::print("  frame time       {:>12.2f} ns measured, {:.2f} ns golden{}\n", frame_time_s * 1e9, gt.frame_time_s * 1e9,
             timing_matches ? "" : "  (MISMATCH)");
  fmt::print("  frame rate       {:>12.3f} kHz measured, {:.3f} kHz golden\n", frame_rate_Hz / 1e3, gt.frame_access_rate_Hz / 1e3);
  fmt::print("  range maps       {:>12.2f} /s\n\n", frame_rate_Hz / cfg.timing.beam_positions);
  fmt::print("  points visible {}, detected {}, missed {}, false {}\n", m.visible, m.detected, m.missed, m.false_detections);
  if (m.detected)
    fmt::print("  range error      rms {:.3f} mm ({:.4f} px), mean {:+.3f} mm, max |e| {:.3f} mm\n", m.rms_m() * 1e3, m.rms_px(),
               m.mean_m() * 1e3, m.max_abs_m * 1e3);
  fmt::print("  wall time        {:.2f} s, {:.3g} simulated cycles/s\n\n", wall_s, res.cycles / res.wall_time_s);
  for (const auto& w : written) fmt::print("  wrote {}\n", w);
  if (!opt.trace.empty()) fmt::print("  wrote {}\n", opt.trace);
  return kExitOk;
}

}  // namespace rangesim::app
