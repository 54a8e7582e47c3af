#include "systemc/tof_lockin/simulate.h"

#include <chrono>
#include <cmath>
#include <fmt/format.h>
#include <map>
#include <memory>
#include <stdexcept>

#include "core/params.h"
#include "core/tof_lockin/config.h"
#include "core/user_error.h"
#include "scene/physical.h"
#include "golden/common/frame_timing.h"
#include "golden/tof_lockin/lockin_point.h"
#include "golden/tof_lockin/model.h"
#include "golden/tof_lockin/pulse_timing.h"
#include "scene/scene.h"
#include "systemc/tof_lockin/lockin_scene.h"
#include "systemc/tof_lockin/scene_adapter.h"
#include "systemc/tof_lockin/sensor.h"

namespace rangesim::systemc {

namespace {

namespace lk = rangesim::systemc::lockin;
using Clock = std::chrono::steady_clock;

long long checked_frames(const SimulationRequest& req, const golden::FrameTiming& gt) {
  const long long frames = req.frames ? *req.frames : gt.frames_per_range_map;
  if (frames < 1 || frames > 100000)
    throw UserError(fmt::format("--frames {}: allowed 1 <= N <= 100000 (sensor frames; a range map is {})", frames,
                                gt.frames_per_range_map));
  return frames;
}

// Time step of the pulse/gate overlap integration: at most one step per pulse width (coarser says
// nothing), at least T0 / 1e5 (bounded cost); 1e-9 relative slack so the printed bounds
// themselves are accepted.
void check_time_step(const SimulationRequest& req, const TofLockinConfig& cfg) {
  const double T0 = cfg.source.pulse_width_s;
  if (!(req.time_step_s == 0.0 || (req.time_step_s >= T0 * 1e-5 * (1 - 1e-9) && req.time_step_s <= T0 * (1 + 1e-9))))
    throw UserError(
        fmt::format("--time-step {:g}: allowed 0 (exact, closed form) or {:g} <= S <= {:g} "
                    "s (source.pulse_width_s T0 / 1e5 .. T0)",
                    req.time_step_s, T0 * 1e-5, T0));
}

lk::LockinSimOptions kernel_options(const SimulationRequest& req) {
  lk::LockinSimOptions kopt;
  kopt.noise = !req.noise_free;
  kopt.event_skipping = !req.tick;
  kopt.aggregate = !req.tick && !req.no_aggregate;  // N_acc identical periods as one event, Poisson of the total mean
  kopt.seed = req.seed;
  kopt.time_step_s = req.time_step_s;
  return kopt;
}

// The finished sensor kernel: owned here (bare kernels) or by the SystemC module.
struct ModelRun {
  std::unique_ptr<lk::TofLockinSensorKernel> owned;
  const lk::TofLockinSensorKernel* k = nullptr;
  double sim_time_s = 0;
  long long sc_errors = 0;
  double sim_wall_s = 0;
};

// --trace-pixels inside the simulated window, or by default its centre pixel and first pixel.
std::vector<TracePixel> traced_pixels(const SimulationRequest& req, int R, int C) {
  if (!req.trace_pixels.empty()) return req.trace_pixels;
  std::vector<TracePixel> p{{R / 2, C / 2}};
  if (R / 2 != 0 || C / 2 != 0) p.push_back({0, 0});
  return p;
}

ModelRun run_model(const SimulationRequest& req, const TofLockinConfig& cfg, const lk::LockinSimOptions& kopt,
                   const lk::LockinScene& sc, long long frames, const golden::FrameTiming& gt,
                   const std::string& vcd_base, SimulationHost& host) {
  const int R = sc.window_rows(cfg), C = sc.window_columns(cfg);
  const auto t_sim = Clock::now();
  ModelRun m;
  if (req.kernel_only) {
    m.owned = std::make_unique<lk::TofLockinSensorKernel>(cfg, kopt, R, C, sc.stimulus(cfg), frames);
    const auto progress = host.progress("frame", frames);
    long long reported = 0;
    while (m.owned->step())
      if (m.owned->frame() != reported) progress(reported = m.owned->frame());
    m.sim_time_s = m.owned->time_s();
    m.k = m.owned.get();
  } else {
    lk::TofLockinSensor* mod = nullptr;
    const lk::LockinScRun r = lk::run_tof_lockin_systemc(
        mod, cfg, kopt, R, C, sc.stimulus(cfg), frames, 1.01 * gt.frame_time_s * static_cast<double>(frames) + 1e-6,
        vcd_base.empty() ? "" : vcd_base + ".vcd", traced_pixels(req, R, C));
    m.sc_errors = r.sc_errors;
    m.sim_time_s = r.end_time_s;
    m.k = &mod->kernel();
    if (!r.finished || m.sc_errors > 0)
      throw std::runtime_error(
          fmt::format("the SystemC model reported {} error(s) (finished: {})", m.sc_errors, r.finished));
  }
  m.sim_wall_s = std::chrono::duration<double>(Clock::now() - t_sim).count();
  return m;
}

// The range map averaged over the range maps run, and every value's error against the scene. A
// value counts where the kernel gives one (above readout.detection_threshold_V, not clipped), the
// SNR of its a + b, from its own taps, reaches readout.min_snr and its rms noise from those taps
// is at most readout.max_range_noise_fraction x c T0 / 2 (golden/tof_lockin/validity.h): golden's
// detectability, so a uniform scene's map is valid where evaluate calls the point detectable.
struct Reconstruction {
  RangeMap map;
  long long visible = 0, detected = 0, missed = 0;
  RangeErrorStats err;
};

Reconstruction reconstruct(const lk::TofLockinSensorKernel& k, const lk::LockinScene& sc, int R, int C) {
  Reconstruction out;
  const TofLockinConfig& cfg = k.config();
  out.map.range_m.assign(static_cast<std::size_t>(R), std::vector<double>(static_cast<std::size_t>(C), NAN));
  out.map.truth_m = out.map.range_m;
  out.map.confidence = out.map.range_m;
  for (int c = 0; c < C; ++c) out.map.column_names.push_back(fmt::format("c{}", c));
  for (int r = 0; r < R; ++r)
    for (int c = 0; c < C; ++c) {
      const auto ur = static_cast<std::size_t>(r), uc = static_cast<std::size_t>(c);
      const double truth = sc.distance_at(r, c, C);
      out.map.truth_m[ur][uc] = truth;
      double acc = 0, snr_sum = 0;
      int n = 0;
      for (long long m = 0; m < k.range_maps(); ++m) {
        const double L = k.range_m(m, r, c);
        ++out.visible, snr_sum += k.snr(m, r, c);
        if (!k.range_valid(m, r, c)) {
          ++out.missed;
          continue;
        }
        ++out.detected, ++n, acc += L;
        out.err.add(L - truth);
      }
      if (n) out.map.range_m[ur][uc] = acc / n;
      if (k.range_maps() > 0) out.map.confidence[ur][uc] = snr_sum / static_cast<double>(k.range_maps());
    }
  out.map.confidence_label = "SNR of V1 + V2 from the pixel's own taps, mean over range maps";
  out.map.validity_rule = fmt::format(
      "valid where V1 + V2 >= readout.detection_threshold_V = {:g} V, no tap clipped, its SNR >= readout.min_snr = "
      "{:g} and the range's rms noise from its own taps <= readout.max_range_noise_fraction = {:g} x c T0 / 2 = {:g} m",
      cfg.readout.detection_threshold_V, cfg.readout.min_snr, cfg.readout.max_range_noise_fraction,
      cfg.readout.max_range_noise_fraction * golden::max_range_m(cfg.source));
  return out;
}

// The golden expectation at each distinct scene distance (one range map), and its rms accuracy
// over the detectable pixels.
struct GoldenPoints {
  nlohmann::json points = nlohmann::json::array();
  double rms_m = NAN;
};

GoldenPoints golden_points(const TofLockinConfig& cfg, const lk::LockinScene& sc, int R, int C) {
  std::map<double, int> distances;
  for (int c = 0; c < C; ++c) distances[sc.distance_at(0, c, C)] += R;
  GoldenPoints g;
  double ms = 0;
  long long n = 0;
  for (const auto& [d, count] : distances) {
    const double kk = sc.reference_distance_m / d;
    const golden::LockinPoint pt =
        golden::evaluate_point(cfg, sc.signal_photocurrent_A * kk * kk, sc.background_photocurrent_A, d, 1);
    g.points.push_back({{"distance_m", d},
                        {"pixels", count},
                        {"detect", golden::to_string(pt.detect)},
                        {"mean_m", json_number(pt.mean_m)},
                        {"std_m", json_number(pt.std_m)},
                        {"accuracy_m", json_number(pt.accuracy_m)}});
    if (pt.detect == golden::LockinDetect::Detectable) ms += pt.accuracy_m * pt.accuracy_m * count, n += count;
  }
  g.rms_m = n ? std::sqrt(ms / n) : NAN;
  return g;
}

// frames.csv, the cycles of every frame and whether each phase took its golden count.
struct FrameTiming {
  std::string csv = "frame,led_on,cycles,start_s,end_s";
  nlohmann::json frame_cycles = nlohmann::json::array();
  long long cycles_total = 0;
  bool matches = true;
};

FrameTiming frame_timing(const lk::TofLockinSensorKernel& k, const golden::FrameTiming& gt) {
  FrameTiming t;
  for (int p = 0; p < lk::kPhaseCount; ++p)
    t.csv += fmt::format(",{}", lk::phase_name(static_cast<lk::LockinPhase>(p + 1)));
  t.csv += "\n";
  for (const auto& fr : k.frame_records()) {
    long long total = 0;
    for (int p = 0; p < lk::kPhaseCount; ++p)
      total += fr.cycles[p], t.matches = t.matches && fr.cycles[p] == gt.phases[p].cycles;
    t.csv +=
        fmt::format("{},{},{},{},{}", fr.frame, fr.led_on ? 1 : 0, total, csv_number(fr.start_s), csv_number(fr.end_s));
    for (int p = 0; p < lk::kPhaseCount; ++p) t.csv += fmt::format(",{}", fr.cycles[p]);
    t.csv += "\n";
    t.frame_cycles.push_back(total), t.cycles_total += total;
  }
  return t;
}

nlohmann::json phases_json(const lk::TofLockinSensorKernel& k, const TofLockinConfig& cfg,
                           const golden::FrameTiming& gt) {
  const lk::LockinFrameRecord& first = k.frame_records().front();
  nlohmann::json phases = nlohmann::json::array();
  for (int p = 0; p < lk::kPhaseCount; ++p) {
    const double clk = p < 3 ? cfg.gates.clock_Hz : cfg.readout.clock_Hz;  // gate phases on the gate clock
    phases.push_back({{"name", gt.phases[p].name},
                      {"cycles", first.cycles[p]},
                      {"clock_Hz", clk},
                      {"time_s", static_cast<double>(first.cycles[p]) / clk},
                      {"golden_cycles", gt.phases[p].cycles}});
  }
  return phases;
}

// Everything the summary and the report are made of.
struct Run {
  const SimulationRequest& req;
  const ParamSet& params;
  const TofLockinConfig& cfg;
  const lk::LockinSimOptions& kopt;
  const lk::LockinScene& sc;
  const ModelRun& model;
  const golden::FrameTiming& gt;
  const Reconstruction& rec;
  const GoldenPoints& golden;
  const FrameTiming& timing;
  long long frames;
  double wall_s;
  int R, C;
  double frame_time_s() const { return model.sim_time_s / static_cast<double>(frames); }
};

nlohmann::json summary(const Run& run, const SimulationReport& report) {
  const auto& [req, params, cfg, kopt, sc, model, gt, rec, golden, timing, frames, wall_s, R, C] = run;
  const lk::TofLockinSensorKernel& k = *model.k;
  nlohmann::json j = {
      {"sensor", params.sensor_id()},
      {"preset", params.origin()},
      {"scene", sc.name},
      {"scene_file", sc.file},
      {"target_shape", lk::shape_name(sc.shape)},
      {"harness", req.kernel_only ? "kernel" : "systemc"},
      {"event_skipping", kopt.event_skipping},
      {"aggregation", kopt.aggregate},
      {"time_step_s", kopt.time_step_s},
      {"noise", kopt.noise},
      {"seed", req.seed},
      {"frames", frames},
      {"range_maps", k.range_maps()},
      {"frames_per_range_map", gt.frames_per_range_map},
      {"window_rows", R},
      {"window_columns", C},
      {"pixels_simulated", static_cast<long long>(R) * C},
      {"clock_Hz", cfg.gates.clock_Hz},
      {"readout_clock_Hz", cfg.readout.clock_Hz},
      {"cycles", timing.cycles_total},
      {"gate_cycles", k.gate_cycles()},
      {"readout_cycles", k.readout_cycles()},
      {"frame_cycles", timing.frame_cycles},
      {"events", k.events()},
      {"simulated_time_s", model.sim_time_s},
      {"points_visible", rec.visible},
      {"points_detected", rec.detected},
      {"points_missed", rec.missed},
      {"wall_time_s", wall_s},
      {"simulation_wall_time_s", model.sim_wall_s},
      {"simulated_cycles_per_s", static_cast<double>(timing.cycles_total) / model.sim_wall_s},
      {"sc_errors", model.sc_errors},
  };
  add_timing_json(j, report, gt);
  j["golden"]["accuracy_rms_m"] = json_number(golden.rms_m);
  j["golden"]["points"] = golden.points;
  add_validity_json(j, rec.map);
  rec.err.to_json(j, false);
  return j;
}

SimulationReport report(const Run& run) {
  const auto& [req, params, cfg, kopt, sc, model, gt, rec, golden, timing, frames, wall_s, R, C] = run;
  const long long maps = model.k->range_maps();
  SimulationReport r;
  r.headline = fmt::format("{} on scene '{}' ({}): {} frame{} ({} range map{}), {} x {} pixels, {}, {}",
                           params.sensor_id(), sc.name, lk::shape_name(sc.shape), frames, frames == 1 ? "" : "s", maps,
                           maps == 1 ? "" : "s", R, C, req.kernel_only ? "bare kernels" : "SystemC",
                           req.noise_free ? "noise-free" : fmt::format("noise seed {}", req.seed));
  r.frame_label = "frame";
  set_timing(r, gt, phases_json(*model.k, cfg, gt), timing.frame_cycles.front().get<long long>(), run.frame_time_s(),
             gt.frames_per_range_map, timing.matches);
  r.points_line = fmt::format("pixel values {}, detected {}, missed {}", rec.visible, rec.detected, rec.missed);
  r.error = rec.err;
  r.error_note = fmt::format("(golden accuracy {:.3f} mm)", golden.rms_m * 1e3);
  r.wall_time_s = wall_s;
  r.wall_note = fmt::format("{:.2f} s simulating, {} events", model.sim_wall_s, model.k->events());
  return r;
}

SimulationResult simulate_tof_lockin(const SimulationRequest& req, const ParamSet& params, SimulationHost& host) {
  const auto t_start = Clock::now();
  const TofLockinConfig cfg = tof_lockin_from_params(params);
  if (req.scene.empty())
    throw UserError("--scene is required: a tof-lockin scene file, e.g. scenes/tof-lockin-plane.toml");
  const golden::FrameTiming gt = golden::frame_timing_tof_lockin(params);
  const long long frames = checked_frames(req, gt);
  const std::string vcd_base = host.open_trace();
  if (req.tick && !req.kernel_only)
    throw UserError("--tick selects the kernel's cycle-by-cycle path; use it with --kernel-only");
  check_time_step(req, cfg);
  const SensorRadiometry radiometry = tof_lockin_radiometry(params);
  const lk::LockinScene sc = scene::to_lockin_scene(scene::load_scene(req.scene, "tof-lockin"), cfg, &radiometry);
  fmt::print(stderr, "{}", scene::notes_text(sc.notes, "simulate"));
  {
    lk::LockinGateGeneratorKernel check(cfg);
  }  // T_rep on the gate-clock grid, or UserError before anything is written
  const int R = sc.window_rows(cfg), C = sc.window_columns(cfg);
  check_trace_pixels(req.trace_pixels, 0, R, 0, C, fmt::format("the scene's window of {} x {} pixels", R, C));
  // Two ADC codes and two inputs per pixel and frame are kept, with each pixel's state.
  host.check_memory(static_cast<double>(R) * C * (32.0 * static_cast<double>(frames) + 512),
                    fmt::format("{} x {} pixels x {} frames, two taps each", R, C, frames),
                    "--frames, the scene's window");
  host.open_output(sc.name);
  const lk::LockinSimOptions kopt = kernel_options(req);
  const ModelRun model = run_model(req, cfg, kopt, sc, frames, gt, vcd_base, host);

  SimulationResult out;
  Reconstruction rec = reconstruct(*model.k, sc, R, C);
  const GoldenPoints golden = golden_points(cfg, sc, R, C);
  FrameTiming timing = frame_timing(*model.k, gt);
  const Run run{req, params, cfg,    kopt,   sc,     model,
                gt,  rec,    golden, timing, frames, std::chrono::duration<double>(Clock::now() - t_start).count(),
                R,   C};
  out.report = report(run);
  out.summary = summary(run, out.report);
  if (!sc.notes.empty()) out.summary["scene_notes"] = sc.notes;
  out.frames_csv = std::move(timing.csv);
  out.range_map = std::move(rec.map);
  const long long maps = model.k->range_maps();
  out.range_map.title =
      fmt::format("{} - {} ({} range map{})", sc.name, params.sensor_id(), maps, maps == 1 ? "" : "s");
  out.range_map.x_label = "column";
  return out;
}

}  // namespace

const SimulateEntry& tof_lockin_simulate_entry() {
  static const SimulateEntry e{"tof-lockin", &simulate_tof_lockin, true, true, false, true, false};
  return e;
}

}  // namespace rangesim::systemc
