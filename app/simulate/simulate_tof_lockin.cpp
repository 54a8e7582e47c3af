// rangesim simulate tof-lockin: the clock-level model of the pulsed lock-in ToF
// sensor (bare kernels or SystemC) on a tof-lockin scene; range map by
// eq. 2.25, error against the scene's ground truth and the golden expectation,
// frame timing measured from simulated time beside
// golden::frame_timing_tof_lockin (docs/tof-lockin-clock.md).
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <unistd.h>

#include "app/cli_common.h"
#include "app/cmd_simulate.h"
#include "app/output_dir.h"
#include "app/simulate/simulate_output.h"
#include "app/simulate/simulate_report.h"
#include "app/simulate/trace_output.h"
#include "core/params.h"
#include "core/tof_lockin/config.h"
#include "core/user_error.h"
#include "golden/common/evaluate_sensor.h"
#include "golden/tof_lockin/lockin_point.h"
#include "scene/scene.h"
#include "systemc/tof_lockin/scene_adapter.h"
#include "systemc/tof_lockin/lockin_scene.h"
#include "systemc/tof_lockin/sensor.h"
#include "golden/tof_lockin/model.h"

namespace rangesim::app {

namespace {

namespace fs = std::filesystem;
namespace lk = rangesim::systemc::lockin;
using Clock = std::chrono::steady_clock;

int run_simulate_tof_lockin(const SimulateOptions &opt,
                            const ParamSet &params) {
  const auto t_start = Clock::now();
  const TofLockinConfig cfg = tof_lockin_from_params(params);
  if (opt.scene.empty())
    throw UserError("--scene is required: a tof-lockin scene file, e.g. "
                    "scenes/tof-lockin-plane.toml");
  const golden::FrameTiming gt = golden::frame_timing_tof_lockin(params);
  const long long frames = opt.frames ? *opt.frames : gt.frames_per_range_map;
  if (frames < 1 || frames > 100000)
    throw UserError(fmt::format("--frames {}: allowed 1 <= N <= 100000 (sensor "
                                "frames; a range map is {})",
                                frames, gt.frames_per_range_map));
  TraceOutput trace(opt.trace, opt.kernel_only);
  if (opt.tick && !opt.kernel_only)
    throw UserError("--tick selects the kernel's cycle-by-cycle path; use it "
                    "with --kernel-only");
  // Time step of the pulse/gate overlap integration: at most one step per
  // pulse width (coarser says nothing), at least T0 / 1e5 (bounded cost);
  // 1e-9 relative slack so the printed bounds themselves are accepted.
  const double T0 = cfg.source.pulse_width_s;
  if (!(opt.time_step_s == 0.0 ||
        (opt.time_step_s >= T0 * 1e-5 * (1 - 1e-9) &&
         opt.time_step_s <= T0 * (1 + 1e-9))))
    throw UserError(fmt::format(
        "--time-step {:g}: allowed 0 (exact, closed form) or {:g} <= S <= {:g} "
        "s (source.pulse_width_s T0 / 1e5 .. T0)",
        opt.time_step_s, T0 * 1e-5, T0));
  const lk::LockinScene sc =
      scene::to_lockin_scene(scene::load_scene(opt.scene, "tof-lockin"), cfg);
  {
    lk::LockinGateKernel check(cfg);
  } // T_rep on the gate-clock grid, or UserError before anything is written
  OutputDir out(opt.out.empty() ? "rangesim-out/simulate/" + sc.name : opt.out,
                "--out");

  const int R = sc.window_rows(cfg), C = sc.window_columns(cfg);
  lk::LockinSimOptions kopt;
  kopt.noise = !opt.noise_free;
  kopt.event_skipping = !opt.tick;
  kopt.aggregate = !opt.tick && !opt.no_aggregate; // N_acc identical periods as one event, Poisson
                              // of the total mean
  kopt.seed = opt.seed;
  kopt.time_step_s = opt.time_step_s;

  // ---- Run ----
  const auto t_sim = Clock::now();
  std::unique_ptr<lk::TofLockinSensorKernel> owned;
  const lk::TofLockinSensorKernel *k = nullptr;
  double sim_time_s = 0;
  long long sc_errors = 0;
  if (opt.kernel_only) {
    owned = std::make_unique<lk::TofLockinSensorKernel>(
        cfg, kopt, R, C, sc.stimulus(cfg), frames);
    Progress progress("frame", frames, t_start);
    long long reported = 0;
    while (owned->step())
      if (owned->frame() != reported)
        progress(reported = owned->frame());
    sim_time_s = owned->time_s();
    k = owned.get();
  } else {
    lk::TofLockinSensor *mod = nullptr;
    const lk::LockinScRun r = lk::run_tof_lockin_systemc(
        mod, cfg, kopt, R, C, sc.stimulus(cfg), frames,
        1.01 * gt.frame_time_s * static_cast<double>(frames) + 1e-6,
        trace.enabled() ? trace.vcd_base() + ".vcd" : "");
    sc_errors = r.sc_errors;
    sim_time_s = r.end_time_s;
    k = &mod->kernel();
    if (!r.finished || sc_errors > 0)
      throw std::runtime_error(
          fmt::format("the SystemC model reported {} error(s) (finished: {})",
                      sc_errors, r.finished));
  }
  const double sim_wall_s =
      std::chrono::duration<double>(Clock::now() - t_sim).count();

  // ---- Range map (averaged over the range maps run) and its error ----
  const long long maps = k->range_maps();
  std::vector<double> avg(static_cast<std::size_t>(R) * C, NAN);
  long long visible = 0, detected = 0, missed = 0;
  RangeErrorStats err_stats;
  for (int r = 0; r < R; ++r)
    for (int c = 0; c < C; ++c) {
      const double truth = sc.distance_at(r, c, C);
      double acc = 0;
      int n = 0;
      for (long long m = 0; m < maps; ++m) {
        const double L = k->range_m(m, r, c);
        ++visible;
        if (!std::isfinite(L)) {
          ++missed;
          continue;
        }
        ++detected, ++n, acc += L;
        const double e = L - truth;
        err_stats.add(e);
      }
      if (n)
        avg[static_cast<std::size_t>(r) * C + c] = acc / n;
    }
  // Golden expectation at each distinct scene distance (one range map).
  std::map<double, int> distances;
  for (int c = 0; c < C; ++c)
    distances[sc.distance_at(0, c, C)] += R;
  nlohmann::json golden_points = nlohmann::json::array();
  double golden_ms = 0;
  long long golden_n = 0;
  for (const auto &[d, count] : distances) {
    const double kk = sc.reference_distance_m / d;
    const golden::LockinPoint pt =
        golden::evaluate_point(cfg, sc.signal_photocurrent_A * kk * kk,
                               sc.background_photocurrent_A, d, 1);
    golden_points.push_back({{"distance_m", d},
                             {"pixels", count},
                             {"detect", golden::to_string(pt.detect)},
                             {"mean_m", json_number(pt.mean_m)},
                             {"std_m", json_number(pt.std_m)},
                             {"accuracy_m", json_number(pt.accuracy_m)}});
    if (pt.detect == golden::LockinDetect::Detectable)
      golden_ms += pt.accuracy_m * pt.accuracy_m * count, golden_n += count;
  }
  const double golden_rms = golden_n ? std::sqrt(golden_ms / golden_n) : NAN;

  std::string range_csv = "row";
  for (int c = 0; c < C; ++c)
    range_csv += fmt::format(",c{}", c);
  range_csv += "\n";
  for (int r = 0; r < R; ++r) {
    range_csv += std::to_string(r);
    for (int c = 0; c < C; ++c)
      range_csv += "," + csv_number(avg[static_cast<std::size_t>(r) * C + c]);
    range_csv += "\n";
  }

  // ---- Timing ----
  std::string frames_csv = "frame,led_on,cycles,start_s,end_s";
  for (int p = 0; p < lk::kPhaseCount; ++p)
    frames_csv +=
        fmt::format(",{}", lk::phase_name(static_cast<lk::LockinPhase>(p + 1)));
  frames_csv += "\n";
  bool timing_matches = true;
  for (const auto &fr : k->frame_records()) {
    long long total = 0;
    for (int p = 0; p < lk::kPhaseCount; ++p)
      total += fr.cycles[p],
          timing_matches =
              timing_matches && fr.cycles[p] == gt.phases[p].cycles;
    frames_csv += fmt::format("{},{},{},{},{}", fr.frame, fr.led_on ? 1 : 0,
                              total, csv_number(fr.start_s), csv_number(fr.end_s));
    for (int p = 0; p < lk::kPhaseCount; ++p)
      frames_csv += fmt::format(",{}", fr.cycles[p]);
    frames_csv += "\n";
  }
  const double frame_time_s = sim_time_s / static_cast<double>(frames);
  const double frame_rate_Hz = 1.0 / frame_time_s;
  const lk::LockinFrameRecord &first = k->frame_records().front();
  nlohmann::json phases = nlohmann::json::array();
  long long cycles_total = 0;
  for (int p = 0; p < lk::kPhaseCount; ++p) {
    const double clk = p < 3 ? cfg.gates.clock_Hz : cfg.readout.clock_Hz;
    phases.push_back({{"name", gt.phases[p].name},
                      {"cycles", first.cycles[p]},
                      {"clock_Hz", clk},
                      {"time_s", static_cast<double>(first.cycles[p]) / clk},
                      {"golden_cycles", gt.phases[p].cycles}});
  }
  nlohmann::json frame_cycles = nlohmann::json::array();
  for (const auto &fr : k->frame_records()) {
    long long t = 0;
    for (int p = 0; p < lk::kPhaseCount; ++p)
      t += fr.cycles[p];
    frame_cycles.push_back(t), cycles_total += t;
  }
  const double wall_s =
      std::chrono::duration<double>(Clock::now() - t_start).count();
  nlohmann::json j = {
      {"sensor", params.sensor_id()},
      {"preset", params.origin()},
      {"scene", sc.name},
      {"scene_file", sc.file},
      {"target_shape", lk::shape_name(sc.shape)},
      {"harness", opt.kernel_only ? "kernel" : "systemc"},
      {"event_skipping", kopt.event_skipping},
      {"aggregation", kopt.aggregate},
      {"time_step_s", kopt.time_step_s},
      {"noise", kopt.noise},
      {"seed", opt.seed},
      {"frames", frames},
      {"range_maps", maps},
      {"frames_per_range_map", gt.frames_per_range_map},
      {"window_rows", R},
      {"window_columns", C},
      {"pixels_simulated", static_cast<long long>(R) * C},
      {"clock_Hz", cfg.gates.clock_Hz},
      {"readout_clock_Hz", cfg.readout.clock_Hz},
      {"cycles", cycles_total},
      {"gate_cycles", k->gate_cycles()},
      {"readout_cycles", k->readout_cycles()},
      {"frame_cycles", frame_cycles},
      {"events", k->events()},
      {"simulated_time_s", sim_time_s},
      {"frame_time_s", frame_time_s},
      {"frame_rate_Hz", frame_rate_Hz},
      {"range_maps_per_s",
       frame_rate_Hz / static_cast<double>(gt.frames_per_range_map)},
      {"phases", phases},
      {"golden",
       {{"frame_cycles", gt.frame_cycles},
        {"frame_time_s", gt.frame_time_s},
        {"frame_access_rate_Hz", gt.frame_access_rate_Hz},
        {"range_maps_per_s", gt.range_maps_per_s},
        {"accuracy_rms_m", json_number(golden_rms)},
        {"points", golden_points}}},
      {"timing_matches_golden", timing_matches},
      {"points_visible", visible},
      {"points_detected", detected},
      {"points_missed", missed},
      {"wall_time_s", wall_s},
      {"simulation_wall_time_s", sim_wall_s},
      {"simulated_cycles_per_s",
       static_cast<double>(cycles_total) / sim_wall_s},
      {"sc_errors", sc_errors},
  };

  err_stats.to_json(j, false);
  out.write("range_map.csv", range_csv);
  out.write("frames.csv", frames_csv);
  std::string warning;
  if (!opt.no_plots) {
    std::vector<std::vector<double>> rows(static_cast<std::size_t>(R));
    for (int r = 0; r < R; ++r)
      rows[static_cast<std::size_t>(r)].assign(avg.begin() + static_cast<std::ptrdiff_t>(r) * C,
                                               avg.begin() + static_cast<std::ptrdiff_t>(r + 1) * C);
    warning = render_range_map(out, rows,
                               fmt::format("{} - {} ({} range map{})", sc.name, params.sensor_id(), maps,
                                           maps == 1 ? "" : "s"),
                               "column");
  }
  SimulateSummary report;
  report.headline = fmt::format("{} on scene '{}' ({}): {} frame{} ({} range map{}), {} x {} pixels, {}, {}",
                             params.sensor_id(), sc.name, lk::shape_name(sc.shape), frames, frames == 1 ? "" : "s", maps,
                             maps == 1 ? "" : "s", R, C, opt.kernel_only ? "bare kernels" : "SystemC",
                             opt.noise_free ? "noise-free" : fmt::format("noise seed {}", opt.seed));
  report.phases = phases;
  report.frame_label = "frame";
  report.frame_cycles = frame_cycles.front().get<long long>(), report.golden_frame_cycles = gt.frame_cycles;
  report.frame_time_s = frame_time_s, report.golden_frame_time_s = gt.frame_time_s;
  report.frame_rate_Hz = frame_rate_Hz, report.golden_frame_rate_Hz = gt.frame_access_rate_Hz;
  report.timing_matches = timing_matches;
  report.range_maps_per_s = frame_rate_Hz / static_cast<double>(gt.frames_per_range_map);
  report.frames_per_range_map = gt.frames_per_range_map;
  report.points_line = fmt::format("pixel values {}, detected {}, missed {}", visible, detected, missed);
  report.error = err_stats;
  report.error_note = fmt::format("(golden accuracy {:.3f} mm)", golden_rms * 1e3);
  report.wall_time_s = wall_s;
  report.wall_note = fmt::format("{:.2f} s simulating, {} events", sim_wall_s, k->events());
  return finish_simulate(opt, out, trace, j, warning, report);
}

}  // namespace

const SimulateEntry& tof_lockin_simulate_entry() {
  static const SimulateEntry e{"tof-lockin", &run_simulate_tof_lockin, true, true};
  return e;
}

} // namespace rangesim::app
