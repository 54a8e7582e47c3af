#include "systemc/tof_spad/simulate.h"

#include <chrono>
#include <cmath>
#include <fmt/format.h>
#include <stdexcept>

#include "core/params.h"
#include "core/tof_spad/config.h"
#include "core/user_error.h"
#include "scene/physical.h"
#include "golden/common/frame_timing.h"
#include "golden/tof_spad/model.h"
#include "systemc/tof_spad/scene_adapter.h"
#include "systemc/tof_spad/sensor.h"
#include "systemc/tof_spad/nonideal_rates.h"

namespace rangesim::systemc {

namespace {

namespace sp = rangesim::systemc::spad;
using Clock = std::chrono::steady_clock;

// The preset's array and the flags, checked in the order the command has always reported them.
struct Checked {
  TofSpadConfig cfg;
  int array_rows = 0, array_columns = 0;
  long long frames = 0;
};

Checked check(const SimulationRequest& req, const ParamSet& params) {
  Checked c{tof_spad_from_params(params), static_cast<int>(params.integer("array.rows")),
            static_cast<int>(params.integer("array.columns")), 0};
  if (c.array_columns % c.cfg.tdc.columns_per_tdc != 0)
    throw UserError(fmt::format("{}: array.columns = {} is not a multiple of tdc.columns_per_tdc = {}", params.origin(),
                                c.array_columns, c.cfg.tdc.columns_per_tdc));
  if (req.scene.empty()) throw UserError("--scene is required: a scene file, e.g. scenes/tof-spad-plane.toml");
  c.frames = req.frames ? *req.frames : 1;
  if (c.frames < 1 || c.frames > 10000)
    throw UserError(fmt::format("--frames {}: allowed 1 <= N <= 10000 (tof-spad frames; a range map is {})", c.frames,
                                c.cfg.evaluation.frames_averaged));
  if (req.tick && !req.kernel_only)
    throw UserError("--tick / --no-event-skip selects the kernel's cycle-by-cycle TDC path; use it with --kernel-only");
  return c;
}

sp::TofSpadKernelOptions kernel_options(const SimulationRequest& req) {
  sp::TofSpadKernelOptions kopt;
  kopt.seed = req.seed;
  kopt.event_skipping = !req.tick;  // per clock: every TDC cycle evaluated (identical histograms, tested)
  // Laser cycles drawn at once where they are independent (systemc/tof_spad/spad_aggregation.h); the
  // preset's dead time and afterpulses make them dependent, so its default run is per cycle.
  kopt.aggregate = !req.tick && !req.no_aggregate;
  // Sparse pixels: TDC groups outside the beam (background only) as one class, in closed form where
  // exact (spad_aggregation.h); --dense simulates every pixel of the array one by one.
  kopt.sparse = !req.tick && !req.dense;
  if (req.noise_free) kopt.noise = sp::SpadNoise::none();
  return kopt;
}

// --trace-pixels, or by default the centre pixel of the simulated window.
std::vector<TracePixel> traced_pixels(const SimulationRequest& req, const scene::SpadScene& sc) {
  if (!req.trace_pixels.empty()) return req.trace_pixels;
  return {{sc.first_row + sc.rows / 2, sc.first_column + sc.columns / 2}};
}

sp::SystemcRun run_model(const SimulationRequest& req, const sp::TofSpadKernel& kernel, const scene::SpadScene& sc,
                         int columns_per_tdc, long long frames, const std::string& vcd_base, SimulationHost& host,
                         double& sim_wall_s) {
  sp::PixelSelection sel;
  for (int r = sc.first_row; r < sc.first_row + sc.rows; ++r) sel.rows.push_back(r);
  sel.first_group = sc.first_column / columns_per_tdc;
  sel.groups = sc.columns / columns_per_tdc;
  // The scene's rates through multipath, the optics and the chip (systemc/tof_spad/nonideal_rates.h).
  const TofSpadConfig& cfg = kernel.config();
  const sp::RateSource rates = sp::chip_rates(
      cfg, cfg.fixed_pattern.seed, [&sc](int r, int c) { return sc.rates(r, c); }, kernel.rows(), kernel.columns());
  const auto t_sim = Clock::now();
  sp::SystemcRun res = req.kernel_only
                           ? sp::run_tof_spad_kernel(kernel, sel, rates, frames, host.progress("frame", frames))
                           : sp::run_tof_spad_systemc(kernel, sel, rates, frames, vcd_base, traced_pixels(req, sc));
  sim_wall_s = std::chrono::duration<double>(Clock::now() - t_sim).count();
  if (res.traced_groups_drawn_at_once > 0)
    fmt::print(stderr,
               "rangesim simulate: note: --trace: {} traced TDC group row(s) were drawn at once (aggregated or "
               "background class), so their avalanches are not in the waveform; --no-aggregate --dense shows each\n",
               res.traced_groups_drawn_at_once);
  if (res.sc_errors > 0)
    throw std::runtime_error(
        fmt::format("the model reported {} SystemC error(s): see the messages above", res.sc_errors));
  return res;
}

// The range map (mean over the frames), points.csv, frames.csv, and the counts. A pixel's range
// counts where its histogram's peak stands detection_sigma above the histogram's own background
// (golden/tof_spad/validity.h): estimates without that are spurious peaks, no ranges; valid ones
// on pixels outside the beam are false valids and stay out of the error.
struct Reconstruction {
  RangeMap map;
  Table points{{{"frame", Table::Kind::Index},
                {"row", Table::Kind::Index},
                {"column", Table::Kind::Index},
                {"truth_range_m"},
                {"detected", Table::Kind::Flag},
                {"range_m"},
                {"error_m"},
                {"events", Table::Kind::Integer},
                {"valid", Table::Kind::Flag},
                {"significance_sigma"}}};
  std::string frames_csv = "frame,cycles,laser_cycles,histogram_readout,avalanches,photons\n";
  long long points_total = 0, detected = 0, valid = 0, photons = 0, avalanches = 0, groups_agg = 0, groups_cyc = 0;
  long long groups_bg = 0, groups_bg_cyc = 0, background_points = 0, background_detections = 0;
  long long background_valid = 0;
  RangeErrorStats err;
  bool timing_matches = true;
};

// Per pixel over the frames: the sum of valid ranges, their count, the sum of significances.
struct PixelSums {
  std::vector<std::vector<int>> valid;
  std::vector<std::vector<double>> significance;
};

void add_frame(Reconstruction& out, const sp::FrameResult& f, const scene::SpadScene& sc, const golden::FrameTiming& gt,
               double min_sigma, PixelSums& sums) {
  out.frames_csv += fmt::format("{},{},{},{},{},{}\n", f.frame, f.cycles, f.phase_cycles[0], f.phase_cycles[1],
                                f.avalanches, f.photons);
  out.timing_matches = out.timing_matches && f.cycles == gt.frame_cycles && f.phase_cycles[0] == gt.phases[0].cycles &&
                       f.phase_cycles[1] == gt.phases[1].cycles;
  out.photons += f.photons, out.avalanches += f.avalanches;
  out.groups_agg += f.groups_aggregated, out.groups_cyc += f.groups_per_cycle;
  out.groups_bg += f.groups_background, out.groups_bg_cyc += f.groups_background_per_cycle;
  for (const auto& p : f.pixels) {
    const double truth = sc.distance_at(p.row, p.column);
    long long ev = 0;
    for (long long e : p.events) ev += e;
    ++out.points_total;
    double err = NAN;
    const bool lit = sc.lit(p.row, p.column), valid = p.time_s && p.significance >= min_sigma;
    const auto r = static_cast<std::size_t>(p.row - sc.first_row),
               c = static_cast<std::size_t>(p.column - sc.first_column);
    if (lit) out.map.truth_m[r][c] = truth;
    out.background_points += !lit;
    if (p.time_s && !lit) ++out.background_detections;
    if (valid && !lit) ++out.background_valid;
    out.detected += p.time_s.has_value(), out.valid += valid;
    if (valid) {
      if (lit) err = p.range_m - truth, out.err.add(err);
      out.map.range_m[r][c] += p.range_m, ++sums.valid[r][c];  // a sum until every frame is in
    }
    sums.significance[r][c] += p.significance;
    out.points.add_row({static_cast<double>(f.frame), static_cast<double>(p.row), static_cast<double>(p.column), truth,
                        p.time_s ? 1.0 : 0.0, p.time_s ? p.range_m : NAN, err, static_cast<double>(ev),
                        valid ? 1.0 : 0.0, p.significance});
  }
}

Reconstruction reconstruct(const sp::SystemcRun& res, const scene::SpadScene& sc, const golden::FrameTiming& gt,
                           double min_sigma) {
  Reconstruction out;
  const auto rows = static_cast<std::size_t>(sc.rows), columns = static_cast<std::size_t>(sc.columns);
  out.map.range_m.assign(rows, std::vector<double>(columns, 0.0));
  out.map.truth_m.assign(rows, std::vector<double>(columns, NAN));
  PixelSums sums{std::vector<std::vector<int>>(rows, std::vector<int>(columns, 0)),
                 std::vector<std::vector<double>>(rows, std::vector<double>(columns, 0.0))};
  for (const auto& f : res.frames) add_frame(out, f, sc, gt, min_sigma, sums);
  const double frames = static_cast<double>(res.frames.size());
  out.map.confidence.assign(rows, std::vector<double>(columns, NAN));
  for (std::size_t r = 0; r < rows; ++r)
    for (std::size_t c = 0; c < columns; ++c) {
      const int n = sums.valid[r][c];
      out.map.range_m[r][c] = n ? out.map.range_m[r][c] / n : NAN;
      out.map.confidence[r][c] = sums.significance[r][c] / frames;
    }
  out.map.first_row = sc.first_row;
  for (int c = 0; c < sc.columns; ++c) out.map.column_names.push_back(fmt::format("c{}", sc.first_column + c));
  out.map.confidence_label = "peak significance over the histogram's background [sigma], mean over frames";
  out.map.validity_rule = fmt::format(
      "valid where the peak window's counts stand >= evaluation.detection_sigma = {:g} sigma above the background "
      "level of the same histogram (Poisson, corrected for the peak search over the codes)",
      min_sigma);
  return out;
}

// Everything the summary and the report are made of.
struct Run {
  const SimulationRequest& req;
  const ParamSet& params;
  const sp::TofSpadKernelOptions& kopt;
  const sp::TofSpadKernel& kernel;
  const scene::SpadScene& sc;
  const sp::SystemcRun& res;
  const golden::FrameTiming& gt;
  const Reconstruction& rec;
  double sim_wall_s, wall_s;
  double frame_time_s() const { return res.simulated_time_s / static_cast<double>(res.frames.size()); }
};

nlohmann::json phases_json(const Run& run) {
  return systemc::phases_json(run.gt, run.res.frames.front().phase_cycles, run.kernel.clock_Hz());
}

// The sparse-path figures: which laser-cycle path ran, and the background-only pixels.
void add_paths(const Run& run, nlohmann::json& j) {
  const Reconstruction& rec = run.rec;
  j["aggregation"] = {{"requested", run.kopt.aggregate},
                      {"path", rec.groups_agg == 0   ? "per_cycle"
                               : rec.groups_cyc == 0 ? "aggregated"
                                                     : "mixed"},
                      {"groups_aggregated", rec.groups_agg},
                      {"groups_per_cycle", rec.groups_cyc},
                      {"blocker", run.kernel.aggregation_blocker()}};
  j["background_only"] = {{"points", rec.background_points},       {"detections", rec.background_detections},
                          {"valid", rec.background_valid},         {"groups_class", rec.groups_bg},
                          {"groups_per_cycle", rec.groups_bg_cyc}, {"blocker", run.kernel.background_blocker()}};
}

nlohmann::json summary(const Run& run, const SimulationReport& report) {
  const auto& [req, params, kopt, kernel, sc, res, gt, rec, sim_wall_s, wall_s] = run;
  nlohmann::json j = {
      {"sensor", params.sensor_id()},
      {"preset", params.origin()},
      {"scene", sc.name},
      {"scene_file", sc.file},
      {"target_shape", sc.shape},
      {"harness", req.kernel_only ? "kernel" : "systemc"},
      {"event_skipping", !req.tick},
      {"sparse", !req.dense},
      {"window",
       {{"first_row", sc.first_row}, {"rows", sc.rows}, {"first_column", sc.first_column}, {"columns", sc.columns}}},
      {"beam",
       {{"first_row", sc.beam_first_row},
        {"rows", sc.beam_rows},
        {"first_column", sc.beam_first_column},
        {"columns", sc.beam_columns}}},
      {"noise", !req.noise_free},
      {"seed", req.seed},
      {"frames", static_cast<long long>(res.frames.size())},
      {"clock_Hz", kernel.clock_Hz()},
      {"cycles", res.measured_cycles},
      {"simulated_time_s", res.simulated_time_s},
      {"points", rec.points_total},
      {"points_detected", rec.detected},
      {"points_valid", rec.valid},
      {"pixels_simulated", sc.rows * sc.columns},
      {"photons_simulated", rec.photons},
      {"avalanches_simulated", rec.avalanches},
      {"wall_time_s", wall_s},
      {"simulation_wall_time_s", sim_wall_s},
      {"photons_per_s", static_cast<double>(rec.photons) / sim_wall_s},
      {"sc_errors", res.sc_errors},
  };
  add_timing_json(j, report, gt);
  add_paths(run, j);
  add_validity_json(j, rec.map);
  rec.err.to_json(j, false);
  return j;
}

// The wall-time line's note: the simulation speed and which laser-cycle paths ran (and why not).
std::string wall_note(const Run& run) {
  const auto& [req, params, kopt, kernel, sc, res, gt, rec, sim_wall_s, wall_s] = run;
  std::string note = fmt::format(
      "{:.3g} photons/s simulated; laser cycles: {} group rows aggregated, {} per cycle{}",
      static_cast<double>(rec.photons) / sim_wall_s, rec.groups_agg, rec.groups_cyc,
      kopt.aggregate && !kernel.aggregation_blocker().empty() ? " (" + kernel.aggregation_blocker() + ")" : "");
  if (rec.groups_bg + rec.groups_bg_cyc > 0)
    note += fmt::format(
        "; background-only group rows: {} as a class, {} per cycle{}", rec.groups_bg, rec.groups_bg_cyc,
        rec.groups_bg_cyc > 0 && !kernel.background_blocker().empty() ? " (" + kernel.background_blocker() + ")" : "");
  return note;
}

SimulationReport report(const Run& run) {
  const auto& [req, params, kopt, kernel, sc, res, gt, rec, sim_wall_s, wall_s] = run;
  SimulationReport r;
  r.headline =
      fmt::format("tof-spad on scene '{}' ({}): {} frame{}, {}, {}, window {} rows x {} columns", sc.name, sc.shape,
                  res.frames.size(), res.frames.size() == 1 ? "" : "s", req.kernel_only ? "bare kernels" : "SystemC",
                  req.noise_free ? "noise-free" : fmt::format("noise seed {}", req.seed), sc.rows, sc.columns);
  r.frame_label = "frame";
  set_timing(r, gt, phases_json(run), res.frames.front().cycles, run.frame_time_s(), gt.frames_per_range_map,
             rec.timing_matches);
  r.points_line = fmt::format("pixels {} x {} frames, detected {}, valid {}", sc.rows * sc.columns, res.frames.size(),
                              rec.detected, rec.valid);
  if (rec.background_points > 0)
    r.points_line += fmt::format(" ({} of {} background-only points valid: false valids, not in the error)",
                                 rec.background_valid, rec.background_points);
  r.error = rec.err;
  r.wall_time_s = wall_s;
  r.wall_note = wall_note(run);
  return r;
}

SimulationResult simulate_tof_spad(const SimulationRequest& req, const ParamSet& params, SimulationHost& host) {
  const auto t_start = Clock::now();
  const Checked c = check(req, params);
  const std::string vcd_base = host.open_trace();
  const SensorRadiometry radiometry = tof_spad_radiometry(params);
  scene::SpadScene sc = scene::load_spad_scene(req.scene, c.cfg, c.array_rows, c.array_columns, &radiometry);
  fmt::print(stderr, "{}", scene::notes_text(sc.notes, "simulate"));
  if (req.dense) sc.first_row = 0, sc.rows = c.array_rows, sc.first_column = 0, sc.columns = c.array_columns;
  check_trace_pixels(
      req.trace_pixels, sc.first_row, sc.rows, sc.first_column, sc.columns,
      fmt::format("the simulated pixels: rows {}..{}, columns {}..{}; --dense simulates all", sc.first_row,
                  sc.first_row + sc.rows - 1, sc.first_column, sc.first_column + sc.columns - 1));
  const sp::TofSpadKernelOptions kopt = kernel_options(req);
  const sp::TofSpadKernel kernel(c.cfg, c.array_rows, c.array_columns, kopt);
  const int codes = kernel.codes();
  // Every pixel's histogram and armed counts are kept per frame (8 bytes a code each), with its
  // points.csv line and the map's cells.
  const double pixel_frames = static_cast<double>(sc.rows) * sc.columns * static_cast<double>(c.frames);
  host.check_memory(
      pixel_frames * (16.0 * codes + 256),
      fmt::format("{} x {} pixels x {} frames, two {}-code histograms each", sc.rows, sc.columns, c.frames, codes),
      "--frames, the scene's window (or drop --dense)");
  host.open_output(sc.name);
  double sim_wall_s = 0;
  const sp::SystemcRun res =
      run_model(req, kernel, sc, c.cfg.tdc.columns_per_tdc, c.frames, vcd_base, host, sim_wall_s);

  const golden::FrameTiming gt = golden::frame_timing_tof_spad(params);
  SimulationResult out;
  Reconstruction rec = reconstruct(res, sc, gt, c.cfg.evaluation.detection_sigma);
  const Run run{req, params, kopt, kernel,     sc,
                res, gt,     rec,  sim_wall_s, std::chrono::duration<double>(Clock::now() - t_start).count()};
  out.report = report(run);
  out.summary = summary(run, out.report);
  if (!sc.notes.empty()) out.summary["scene_notes"] = sc.notes;
  out.points = std::move(rec.points);
  out.frames_csv = std::move(rec.frames_csv);
  out.range_map = std::move(rec.map);
  out.range_map.title =
      fmt::format("{} — tof-spad ({} frame{})", sc.name, res.frames.size(), res.frames.size() == 1 ? "" : "s");
  out.range_map.x_label = "column in window";
  out.range_map.y_label = "row in window";
  return out;
}

}  // namespace

const SimulateEntry& tof_spad_simulate_entry() {
  static const SimulateEntry e{"tof-spad", &simulate_tof_spad, true, false, false, true, false};
  return e;
}

}  // namespace rangesim::systemc
