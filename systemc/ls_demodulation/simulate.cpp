#include "systemc/common/centre_validity.h"
#include "systemc/common/row_points.h"
#include "systemc/ls_demodulation/simulate.h"

#include <chrono>
#include <cmath>
#include <fmt/format.h>
#include <stdexcept>

#include "core/ls_demodulation/config.h"
#include "core/params.h"
#include "core/user_error.h"
#include "scene/physical.h"
#include "golden/common/frame_timing.h"
#include "golden/ls_demodulation/model.h"
#include "systemc/ls_demodulation/scene_optics.h"
#include "systemc/ls_demodulation/sensor.h"

namespace rangesim::systemc {

namespace {

using Clock = std::chrono::steady_clock;

LsDemodulationConfig checked_config(const SimulationRequest& req, const ParamSet& params) {
  LsDemodulationConfig cfg = ls_demodulation_from_params(params);
  if (cfg.comparator.adc_bits != 1)
    throw UserError(
        fmt::format("{}: comparator.adc_bits = {}: the clock-level model has the 1-bit comparator only; allowed: 1",
                    params.origin(), cfg.comparator.adc_bits));
  if (req.scene.empty()) throw UserError("--scene is required: a scene file, e.g. scenes/ls-demodulation-plane.toml");
  return cfg;
}

long long checked_frames(const SimulationRequest& req, const golden::FrameTiming& gt) {
  const long long frames = req.frames ? *req.frames : gt.frames_per_range_map;
  if (frames < 1 || frames > 100000)
    throw UserError(fmt::format("--frames {}: allowed 1 <= N <= 100000 (frames; a range map is {})", frames,
                                gt.frames_per_range_map));
  return frames;
}

DemodKernelOptions kernel_options(const SimulationRequest& req) {
  DemodKernelOptions kopt;
  kopt.event_skipping = !req.tick;
  kopt.aggregate = !req.tick && !req.no_aggregate;  // ticking steps every period anyway
  kopt.seed = req.seed;
  if (req.noise_free) kopt.noise = DemodNoiseSwitches::none();
  return kopt;
}

// --trace-pixels inside the array (or a UserError), by default the centre pixel.
std::vector<TracePixel> traced_pixels(const SimulationRequest& req, const LsDemodulationConfig& cfg) {
  check_trace_pixels(req.trace_pixels, 0, cfg.pixel.rows, 0, cfg.pixel.columns,
                     fmt::format("the pixel array of {} x {}", cfg.pixel.rows, cfg.pixel.columns));
  if (!req.trace_pixels.empty()) return req.trace_pixels;
  return {{cfg.pixel.rows / 2, cfg.pixel.columns / 2}};
}

DemodRunResult run_model(const SimulationRequest& req, const ParamSet& params, const LsDemodulationConfig& cfg,
                         const DemodKernelOptions& kopt, const scene::DemodOptics& optics, long long frames,
                         const std::string& vcd_base, SimulationHost& host) {
  const DemodStimulusSource source = [&optics](std::uint64_t f, DemodStimulus& s) { optics.stimulus(f, s); };
  const DemodProgress on_frame = host.progress("frame", frames);
  DemodRunResult res;
  try {
    res = req.kernel_only ? run_demod_kernel(cfg, kopt, source, frames, on_frame)
                          : run_demod_systemc(cfg, kopt, source, frames, vcd_base, on_frame, traced_pixels(req, cfg));
  } catch (const std::invalid_argument& e) {
    throw UserError(fmt::format("{}: {}", params.origin(), e.what()));
  }
  if (res.sc_errors > 0) throw std::runtime_error(fmt::format("the model reported {} SystemC error(s)", res.sc_errors));
  if (static_cast<long long>(res.frames.size()) != frames)
    throw std::runtime_error(fmt::format("the simulation ended after {} of {} frames", res.frames.size(), frames));
  return res;
}

// The range map, points.csv and frames.csv, and the counts against the ground truth.
struct Reconstruction {
  RangeMap map;
  Table points;
  std::string frames_csv;
  long long visible = 0, detected = 0, missed = 0, false_det = 0;
  RangeErrorStats err;
  bool timing_matches = true;
};

// One row of one frame: the range, its error against the truth, its points.csv line. The row's
// range counts when enough of the frame's decisions found the spot and its centre lies inside the
// edge margin.
void add_point(Reconstruction& out, const scene::DemodOptics& optics, const DemodFrameResult& fr, int r, std::size_t f,
               const LsDemodulationConfig& cfg) {
  const auto b = static_cast<long long>(fr.frame);
  const auto& rr = fr.rows[static_cast<std::size_t>(r)];
  const bool vis = optics.visible(b, r);
  const double fraction = static_cast<double>(rr.detections) / cfg.grid.detections;
  const bool valid = centre_valid(rr.detections, cfg.grid.detections, rr.centre_px(), cfg.pixel.columns,
                                  cfg.min_detecting_fraction, cfg.edge_margin_px);
  out.map.confidence[static_cast<std::size_t>(r)][f] = fraction;
  const double truth_x = optics.centre_px(b, r),
               truth_z = optics.visible(b, r) || optics.range_m(b, r) > 0 ? optics.range_m(b, r) : NAN;
  double range = NAN, err_px = NAN, err_m = NAN;
  if (valid) {
    range = optics.range_from_centre_m(b, rr.centre_px());
    out.map.range_m[static_cast<std::size_t>(r)][f] = range;
  }
  if (vis) {
    ++out.visible;
    out.map.truth_m[static_cast<std::size_t>(r)][f] = truth_z;
    if (valid && std::isfinite(range)) {
      ++out.detected;
      err_px = rr.centre_px() - truth_x;
      err_m = range - truth_z;
      out.err.add(err_m, err_px);
    } else {
      ++out.missed;
    }
  } else if (valid) {
    ++out.false_det;
  }
  if (vis || rr.valid())
    out.points.add_row({static_cast<double>(fr.frame), static_cast<double>(r), vis ? 1.0 : 0.0, truth_x, truth_z,
                        rr.valid() ? 1.0 : 0.0, rr.valid() ? rr.centre_px() : NAN, range, err_px, err_m,
                        valid ? 1.0 : 0.0, fraction});
}

Reconstruction reconstruct(const DemodRunResult& res, const scene::DemodOptics& optics, const LsDemodulationConfig& cfg,
                           const golden::FrameTiming& gt) {
  Reconstruction out;
  const int rows = cfg.pixel.rows;
  out.map.range_m.assign(static_cast<std::size_t>(rows), std::vector<double>(res.frames.size(), NAN));
  out.map.truth_m = out.map.range_m;
  out.map.confidence = out.map.range_m;
  out.map.confidence_label = "fraction of the frame's correlation decisions that found the spot";
  out.map.validity_rule = fmt::format(
      "valid where a row's centre was found by >= validity.min_detecting_fraction = {:g} of the {} decision(s) of "
      "its frame (at least one) and lies >= validity.edge_margin_px = {:g} px inside the first and last column",
      cfg.min_detecting_fraction, cfg.grid.detections, cfg.edge_margin_px);
  out.points = row_points_table(false);
  out.frames_csv = "frame,cycles,end_cycle";
  for (const auto& p : gt.phases) out.frames_csv += "," + p.name;
  out.frames_csv += ",rows_detected\n";
  for (std::size_t f = 0; f < res.frames.size(); ++f) {
    const auto& fr = res.frames[f];
    out.frames_csv += fmt::format("{},{},{}", fr.frame, fr.cycles, fr.end_cycle);
    for (std::size_t i = 0; i < fr.phase_cycles.size(); ++i) {
      out.frames_csv += fmt::format(",{}", fr.phase_cycles[i]);
      out.timing_matches = out.timing_matches && i < gt.phases.size() && fr.phase_cycles[i] == gt.phases[i].cycles;
    }
    out.timing_matches = out.timing_matches && fr.cycles == gt.frame_cycles;
    out.frames_csv += fmt::format(",{}\n", fr.rows_detected());
    for (int r = 0; r < rows; ++r) add_point(out, optics, fr, r, f, cfg);
  }
  for (const auto& fr : res.frames) out.map.column_names.push_back(fmt::format("b{}", fr.frame));
  return out;
}

// Everything the summary and the report are made of.
struct Run {
  const SimulationRequest& req;
  const ParamSet& params;
  const LsDemodulationConfig& cfg;
  const DemodKernelOptions& kopt;
  const scene::DemodScene& sc;
  const DemodRunResult& res;
  const golden::FrameTiming& gt;
  const Reconstruction& rec;
  double wall_s;
  double frame_time_s() const { return res.simulated_time_s / static_cast<double>(res.frames.size()); }
};

nlohmann::json phases_json(const Run& run) {
  return systemc::phases_json(run.gt, run.res.frames.front().phase_cycles, run.cfg.readout.clock_Hz);
}

nlohmann::json summary(const Run& run, const SimulationReport& report) {
  const auto& [req, params, cfg, kopt, sc, res, gt, rec, wall_s] = run;
  nlohmann::json j = {
      {"sensor", params.sensor_id()},
      {"preset", params.origin()},
      {"scene", sc.name},
      {"scene_file", sc.file},
      {"target_shape", sc.shape},
      {"harness", req.kernel_only ? "kernel" : "systemc"},
      {"event_skipping", !req.tick},
      {"aggregation",
       {{"requested", kopt.aggregate},
        {"path", kopt.aggregate ? "aggregated" : "per_period"},
        {"periods_per_window", cfg.correlator.cycles}}},
      {"noise", !req.noise_free},
      {"seed", req.seed},
      {"frames", static_cast<long long>(res.frames.size())},
      {"clock_Hz", cfg.readout.clock_Hz},
      {"cycles", res.cycles},
      {"simulated_time_s", res.simulated_time_s},
      {"points_visible", rec.visible},
      {"points_detected", rec.detected},
      {"points_missed", rec.missed},
      {"points_false", rec.false_det},
      {"wall_time_s", wall_s},
      {"simulation_wall_time_s", res.wall_time_s},
      {"simulated_cycles_per_s", res.cycles / res.wall_time_s},
      {"sc_errors", res.sc_errors},
  };
  add_timing_json(j, report, gt);
  j["golden"]["frames_per_range_map"] = gt.frames_per_range_map;
  add_validity_json(j, rec.map);
  rec.err.to_json(j, true);
  return j;
}

SimulationReport report(const Run& run) {
  const auto& [req, params, cfg, kopt, sc, res, gt, rec, wall_s] = run;
  SimulationReport r;
  const char* path = req.tick         ? " (ticking)"
                     : kopt.aggregate ? " (event skipping, periods aggregated)"
                                      : " (event skipping, period by period)";
  r.headline =
      fmt::format("{} on scene '{}' ({}): {} frame{}, {}{}, {}", params.sensor_id(), sc.name, sc.shape,
                  res.frames.size(), res.frames.size() == 1 ? "" : "s", req.kernel_only ? "bare kernels" : "SystemC",
                  path, req.noise_free ? "noise-free" : fmt::format("noise seed {}", req.seed));
  r.frame_label = "frame";
  set_timing(r, gt, phases_json(run), res.frames.front().cycles, run.frame_time_s(), gt.frames_per_range_map,
             rec.timing_matches);
  r.points_line = fmt::format("points visible {}, detected {}, missed {}, false {}", rec.visible, rec.detected,
                              rec.missed, rec.false_det);
  r.error = rec.err, r.error_in_px = true;
  r.wall_time_s = wall_s;
  r.wall_note = fmt::format("{:.3g} simulated cycles/s", res.cycles / res.wall_time_s);
  return r;
}

SimulationResult simulate_ls_demodulation(const SimulationRequest& req, const ParamSet& params, SimulationHost& host) {
  const auto t_start = Clock::now();
  const LsDemodulationConfig cfg = checked_config(req, params);
  const std::string vcd_base = host.open_trace();
  const golden::FrameTiming gt = golden::frame_timing_ls_demodulation(params);
  const long long frames = checked_frames(req, gt);
  const scene::DemodScene sc = scene::load_demod_scene(req.scene, cfg, params);
  fmt::print(stderr, "{}", scene::notes_text(sc.notes, "simulate"));
  const scene::DemodOptics optics{cfg, sc};
  // Per frame and row: the result, the activation bits, its points.csv line and the map's cells.
  host.check_memory(static_cast<double>(frames) * cfg.pixel.rows * (256.0 + cfg.pixel.columns / 8.0),
                    fmt::format("{} frames x {} rows", frames, cfg.pixel.rows), "--frames");
  host.open_output(sc.name);
  const DemodKernelOptions kopt = kernel_options(req);
  const DemodRunResult res = run_model(req, params, cfg, kopt, optics, frames, vcd_base, host);

  SimulationResult out;
  Reconstruction rec = reconstruct(res, optics, cfg, gt);
  const Run run{
      req, params, cfg, kopt, sc, res, gt, rec, std::chrono::duration<double>(Clock::now() - t_start).count()};
  out.report = report(run);
  out.summary = summary(run, out.report);
  if (!sc.notes.empty()) out.summary["scene_notes"] = sc.notes;
  out.points = std::move(rec.points);
  out.frames_csv = std::move(rec.frames_csv);
  out.range_map = std::move(rec.map);
  out.range_map.title = fmt::format("{} — {} ({} frames)", sc.name, params.sensor_id(), res.frames.size());
  out.range_map.x_label = "beam position (frame)";
  return out;
}

}  // namespace

const SimulateEntry& ls_demodulation_simulate_entry() {
  static const SimulateEntry e{"ls-demodulation", &simulate_ls_demodulation, true, false, false, true, false};
  return e;
}

}  // namespace rangesim::systemc
