#include "systemc/common/centre_validity.h"
#include "systemc/common/row_points.h"
#include "systemc/ls_conventional/simulate.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <memory>
#include <fmt/format.h>
#include <stdexcept>
#include <vector>

#include "core/ls_conventional/config.h"
#include "core/params.h"
#include "core/user_error.h"
#include "scene/physical.h"
#include "golden/ls_conventional/frame_timing.h"
#include "scene/scene.h"
#include "systemc/ls_conventional/scene_optics.h"
#include "systemc/ls_conventional/sensor.h"

namespace rangesim::systemc {

namespace {

using Clock = std::chrono::steady_clock;

// The preset and the flags, checked in the order the command has always reported them.
struct Checked {
  LsConventionalConfig cfg;
  long long frames = 0;  // frame accesses
};

Checked check(const SimulationRequest& req, const ParamSet& params) {
  Checked c{ls_conventional_from_params(params), 0};
  if (c.cfg.comparator.adc_bits != 1)
    throw UserError(
        fmt::format("{}: comparator.adc_bits = {}: the clock-level model has the 1-bit comparator only; allowed: 1",
                    params.origin(), c.cfg.comparator.adc_bits));
  if (req.scene.empty()) throw UserError("--scene is required: a scene file, e.g. scenes/plane.toml");
  c.frames = req.frames ? *req.frames : c.cfg.timing.beam_positions;
  if (c.frames < 1 || c.frames > 1000000)
    throw UserError(fmt::format("--frames {}: allowed 1 <= N <= 1000000 (frame accesses; a range map is {})", c.frames,
                                c.cfg.timing.beam_positions));
  return c;
}

SensorRunResult run_model(const SimulationRequest& req, const LsConventionalConfig& cfg,
                          const scene::SceneOptics& optics, long long frames, const std::string& vcd_base,
                          SimulationHost& host) {
  SensorKernelOptions kopt;
  kopt.event_skipping = !req.tick;
  kopt.frame_extents = false;  // the map and the points read the pins only
  kopt.pixel.seed = req.seed;
  kopt.pixel.sparse = !req.dense;
  if (req.noise_free) kopt.pixel.noise = PixelNoiseConfig::none();
  SensorRunOptions run;
  run.frames = frames;
  run.vcd_base = vcd_base;
  run.traced_rows = req.trace_rows;
  if (run.traced_rows.empty())
    for (int r : {0, cfg.pixel.rows / 4, cfg.pixel.rows / 2, cfg.pixel.rows - 1}) run.traced_rows.push_back(r);
  for (int r : run.traced_rows)
    if (r < 0 || r >= cfg.pixel.rows)
      throw UserError(
          fmt::format("--trace-rows {}: allowed 0..{} (pixel.rows = {})", r, cfg.pixel.rows - 1, cfg.pixel.rows));
  check_trace_pixels(req.trace_pixels, 0, cfg.pixel.rows, 0, cfg.pixel.columns,
                     fmt::format("the pixel array of {} x {}", cfg.pixel.rows, cfg.pixel.columns));
  run.traced_pixels = req.trace_pixels;
  if (run.traced_pixels.empty()) run.traced_pixels.push_back({cfg.pixel.rows / 2, cfg.pixel.columns / 2});
  run.progress = host.progress("frame access", frames);
  if (req.kernel_only) run.threads = req.threads;  // consecutive frame accesses each: the same results
  const StimulusSource source = [&optics](std::uint64_t f, FrameStimulus& s) { optics.stimulus(f, s); };
  SensorRunResult res =
      req.kernel_only ? run_sensor_kernel(cfg, kopt, source, run) : run_sensor_systemc(cfg, kopt, source, run);
  if (!res.errors.empty() || res.sc_errors > 0)
    throw std::runtime_error(fmt::format("the model reported {} error(s): {}", res.errors.size() + res.sc_errors,
                                         res.errors.empty() ? "see the SystemC messages above" : res.errors.front()));
  return res;
}

// The range map, points.csv and frames.csv, and the counts against the ground truth.
struct Reconstruction {
  RangeMap map;
  std::vector<std::uint8_t> valid;  // per frame access and row (frame by frame): its centre is valid
  Table points;
  std::string frames_csv;
  long long visible = 0, detected = 0, missed = 0, false_detections = 0;
  RangeErrorStats err;
  bool timing_matches = true;
  std::unique_ptr<MapWork> map_work;  // after `map`: ends (waits) before the map's storage goes
};

// One row of one frame access: its truth, its centre and what follows: the range counts when enough
// of the samplings found the spot and its centre lies inside the edge margin (cfg.validity).
// A row has a points.csv line where the stripe is on it or its centre processor found a centre.
bool listed(bool visible, bool detected) { return visible || detected; }

// The share of the samplings that found the spot on a row.
double detecting_fraction(const CentreProcessorPins& p, int samplings) {
  return static_cast<double>(p.count) / samplings;
}

// A row's errors against its truth, where the stripe is visible and the centre valid (else NaN).
struct RowErrors {
  double px = NAN, m = NAN;
};
RowErrors row_errors(bool visible, bool valid, double centre_px, double truth_centre_px, double range_m,
                     double truth_range_m) {
  if (!(visible && valid)) return {};
  return {centre_px - truth_centre_px, range_m - truth_range_m};
}

// A map cell of one row of one frame access: the share of the samplings that found the spot, and
// its range where enough of them found it and its centre lies inside the edge margin (cfg.validity).
struct Cell {
  double fraction = 0, range = NAN;
  bool valid = false;
};
Cell cell_of(const scene::SceneOptics& optics, const CentreProcessorPins& p, int b, const LsConventionalConfig& cfg) {
  Cell c;
  c.fraction = detecting_fraction(p, cfg.multisampling.samplings);
  c.valid = centre_valid(p.count, cfg.multisampling.samplings, p.centre_px(), cfg.pixel.columns,
                         cfg.validity.min_detecting_fraction, cfg.validity.edge_margin_px);
  if (c.valid) c.range = optics.range_from_centre_m(b, p.centre_px());
  return c;
}

// A cell with its truth and its errors against it.
struct Point {
  scene::RowTruth t;
  CentreProcessorPins p;
  double range = NAN, err_px = NAN, err_m = NAN;
  bool valid = false;
  bool listed() const { return systemc::listed(t.visible, p.valid); }
};

Point point_of(const scene::RowTruth& t, const CentreProcessorPins& p, bool valid, double range) {
  Point x;
  x.t = t;
  x.p = p;
  x.valid = valid;
  x.range = range;
  const RowErrors e = row_errors(x.t.visible, x.valid, x.p.centre_px(), x.t.centre_px, x.range, x.t.range_m);
  x.err_px = e.px, x.err_m = e.m;
  return x;
}

// The counts of one point.
void add_point(Reconstruction& out, const Point& x) {
  if (x.t.visible) {
    ++out.visible;
    if (x.valid) {
      ++out.detected;
      out.err.add(x.err_m, x.err_px);
    } else {
      ++out.missed;
    }
  } else if (x.valid) {
    ++out.false_detections;
  }
}

Table points_table() { return row_points_table(true); }

// What a points row takes from its Point besides the frame's pins, kept by reconstruct() so that
// writing the table does not work the truth and the range out again (their divisions were most
// of the writing's time): rows x frames cells, frame by frame, 26 bytes a cell where the table's
// doubles would be 104.
struct PointCells {
  std::vector<double> truth_centre_px, truth_range_m;  // NaN where the beam misses the target
  std::vector<double> range_m;                         // NaN where the centre is not valid
  std::vector<std::uint8_t> visible, valid;
  explicit PointCells(std::size_t n)
      : truth_centre_px(n, NAN), truth_range_m(n, NAN), range_m(n, NAN), visible(n, 0), valid(n, 0) {}
  void keep(std::size_t i, const Point& x) {
    truth_centre_px[i] = x.t.hit ? x.t.centre_px : NAN;
    truth_range_m[i] = x.t.hit ? x.t.range_m : NAN;
    range_m[i] = x.range;
    visible[i] = x.t.visible;
    valid[i] = x.valid;
  }
};

// The points table's rows made when it is written, block by block (a full map's 137,000 points
// are never held whole as doubles): the same points in the same order as reconstruct() counts them.
void produce_points(const SensorRunResult& res, const PointCells& cells, const scene::SceneOptics& optics,
                    const LsConventionalConfig& cfg, const Table::BlockSink& sink) {
  constexpr std::size_t kBlockRows = 2048, kColumns = 13;
  std::vector<double> block;
  block.reserve(kBlockRows * kColumns);
  std::size_t i = 0;
  for (const FrameResult& fr : res.frames) {
    const double frame = static_cast<double>(fr.frame), b = optics.beam_position(fr.frame);
    for (int r = 0; r < cfg.pixel.rows; ++r, ++i) {
      const CentreProcessorPins& p = fr.rows[static_cast<std::size_t>(r)];
      const bool visible = cells.visible[i], valid = cells.valid[i];
      if (!listed(visible, p.valid)) continue;
      const RowErrors e =
          row_errors(visible, valid, p.centre_px(), cells.truth_centre_px[i], cells.range_m[i], cells.truth_range_m[i]);
      block.insert(block.end(),
                   {frame, b, static_cast<double>(r), visible ? 1.0 : 0.0, cells.truth_centre_px[i],
                    cells.truth_range_m[i], p.valid ? 1.0 : 0.0, p.valid ? p.centre_px() : NAN, cells.range_m[i], e.px,
                    e.m, valid ? 1.0 : 0.0, detecting_fraction(p, cfg.multisampling.samplings)});
      if (block.size() == kBlockRows * kColumns) {
        sink(block.data(), kBlockRows);
        block.clear();
      }
    }
  }
  if (!block.empty()) sink(block.data(), block.size() / kColumns);
}

// The map's cells (range_m, confidence) and what labels it; truth_m all NaN until map_truth() fills it.
Reconstruction map_cells(const SensorRunResult& res, const scene::SceneOptics& optics,
                         const LsConventionalConfig& cfg) {
  Reconstruction out;
  const int rows = cfg.pixel.rows;
  out.map.range_m.assign(static_cast<std::size_t>(rows), std::vector<double>(res.frames.size(), NAN));
  out.map.truth_m = out.map.range_m;
  out.map.confidence = out.map.range_m;
  out.valid.assign(res.frames.size() * static_cast<std::size_t>(rows), 0);
  out.map.confidence_label = "fraction of the samplings that found the spot";
  out.map.validity_rule = fmt::format(
      "valid where a row's centre was found by >= validity.min_detecting_fraction = {:g} of its {} samplings (at "
      "least one) and lies >= validity.edge_margin_px = {:g} px inside the first and last column",
      cfg.validity.min_detecting_fraction, cfg.multisampling.samplings, cfg.validity.edge_margin_px);
  for (std::size_t f = 0, i = 0; f < res.frames.size(); ++f) {
    const FrameResult& fr = res.frames[f];
    const int b = optics.beam_position(fr.frame);
    out.map.column_names.push_back(fmt::format("b{}", b));
    for (std::size_t r = 0; r < static_cast<std::size_t>(rows); ++r, ++i) {
      const Cell c = cell_of(optics, fr.rows[r], b, cfg);
      out.map.confidence[r][f] = c.fraction;
      out.map.range_m[r][f] = c.range;
      out.valid[i] = c.valid;
    }
  }
  return out;
}

// Each cell's truth, frame by frame, beside the map's truth_m (its range where the stripe is
// visible), as the counts and the points table read it.
struct CellTruths {
  std::vector<double> centre_px;     // NaN where the beam misses the target
  std::vector<std::uint8_t> visible;
  std::vector<double> hit_range_m;   // with the points table only: the range wherever the beam meets the target
  scene::RowTruth at(std::size_t i, const RangeMap& map, std::size_t r, std::size_t f) const {
    scene::RowTruth t;
    t.centre_px = centre_px[i];
    t.hit = !std::isnan(t.centre_px);
    t.visible = visible[i] != 0;
    t.range_m = t.visible ? map.truth_m[r][f] : hit_range_m.empty() ? NAN : hit_range_m[i];
    return t;
  }
};

// The map's truth_m and every cell's truth (CellTruths; the hit range with `with_points` only).
CellTruths map_truth(Reconstruction& out, const SensorRunResult& res, const scene::SceneOptics& optics, int rows,
                     bool with_points) {
  const std::size_t n = res.frames.size() * static_cast<std::size_t>(rows);
  CellTruths truths{std::vector<double>(n), std::vector<std::uint8_t>(n), std::vector<double>(with_points ? n : 0)};
  for (std::size_t f = 0, i = 0; f < res.frames.size(); ++f) {
    const int b = optics.beam_position(res.frames[f].frame);
    for (int r = 0; r < rows; ++r, ++i) {
      const scene::RowTruth t = optics.truth(b, r);
      truths.centre_px[i] = t.hit ? t.centre_px : NAN;
      truths.visible[i] = t.visible;
      if (with_points) truths.hit_range_m[i] = t.hit ? t.range_m : NAN;
      if (t.visible) out.map.truth_m[static_cast<std::size_t>(r)][f] = t.range_m;
    }
  }
  return truths;
}

// The counts and errors against the truth, frames.csv and the points table (with `with_points`
// false it has its columns and no rows: nothing kept for it). Frame by frame, the order the
// counts were always summed in.
void score(Reconstruction& out, const CellTruths& truths, const std::shared_ptr<const SensorRunResult>& run,
           const std::shared_ptr<const scene::SceneOptics>& optics_ptr, const LsConventionalConfig& cfg,
           const golden::FrameTiming& gt, bool with_points) {
  const SensorRunResult& res = *run;
  const scene::SceneOptics& optics = *optics_ptr;
  const int rows = cfg.pixel.rows;
  out.frames_csv = "frame,beam_position,cycles,end_cycle,reset,latch,search,address_stream,output,rows_detected\n";
  std::size_t listed = 0;
  auto cells = std::make_shared<PointCells>(with_points ? res.frames.size() * static_cast<std::size_t>(rows) : 0);
  for (std::size_t f = 0, i = 0; f < res.frames.size(); ++f) {
    const FrameResult& fr = res.frames[f];
    const int b = optics.beam_position(fr.frame);
    out.frames_csv += fmt::format("{},{},{},{}", fr.frame, b, fr.cycles, fr.end_cycle);
    for (std::size_t k = 0; k < fr.phase_cycles.size(); ++k) {
      out.frames_csv += fmt::format(",{}", fr.phase_cycles[k]);
      out.timing_matches = out.timing_matches && fr.phase_cycles[k] == gt.phases[k].cycles;
    }
    out.frames_csv += fmt::format(",{}\n", fr.rows_detected());
    for (int r = 0; r < rows; ++r, ++i) {
      const auto row = static_cast<std::size_t>(r);
      const Point x = point_of(truths.at(i, out.map, row, f), fr.rows[row], out.valid[i] != 0, out.map.range_m[row][f]);
      add_point(out, x);
      if (with_points) cells->keep(i, x);
      listed += x.listed() ? 1 : 0;
    }
  }
  out.points = points_table();
  if (!with_points) return;
  out.points.produced_rows = listed;
  out.points.produce = [run, cells, optics_ptr, cfg](const Table::BlockSink& sink) {
    produce_points(*run, *cells, *optics_ptr, cfg, sink);
  };
}

// Everything the summary and the report are made of.
struct Run {
  const SimulationRequest& req;
  const ParamSet& params;
  const LsConventionalConfig& cfg;
  const scene::Scene& sc;
  const SensorRunResult& res;
  const golden::FrameTiming& gt;
  const Reconstruction& rec;
  double wall_s;
  double frame_time_s() const { return res.simulated_time_s / static_cast<double>(res.frames.size()); }
};

nlohmann::json phases_json(const Run& run) {
  return systemc::phases_json(run.gt, run.res.frames.front().phase_cycles, run.cfg.timing.clock_Hz);
}

nlohmann::json summary(const Run& run, const SimulationReport& report) {
  const auto& [req, params, cfg, sc, res, gt, rec, wall_s] = run;
  nlohmann::json frame_cycles = nlohmann::json::array();
  for (const auto& fr : res.frames) frame_cycles.push_back(fr.cycles);
  nlohmann::json j = {
      {"sensor", params.sensor_id()},
      {"preset", params.origin()},
      {"scene", sc.name},
      {"scene_file", sc.file},
      {"target_shape", scene::shape_name(sc.shape)},
      {"harness", req.kernel_only ? "kernel" : "systemc"},
      {"event_skipping", req.kernel_only && !req.tick},
      {"sparse", !req.dense},
      {"noise", !req.noise_free},
      {"seed", req.seed},
      {"frames", static_cast<long long>(res.frames.size())},
      {"beam_positions", cfg.timing.beam_positions},
      {"samplings", cfg.multisampling.samplings},
      {"clock_Hz", cfg.timing.clock_Hz},
      {"cycles", res.cycles},
      {"frame_cycles", frame_cycles},
      {"simulated_time_s", res.simulated_time_s},
      {"points_visible", rec.visible},
      {"points_detected", rec.detected},
      {"points_missed", rec.missed},
      {"points_false", rec.false_detections},
      {"pixels_simulated", res.pixels_simulated},
      {"wall_time_s", wall_s},
      {"simulation_wall_time_s", res.wall_time_s},
      {"simulated_cycles_per_s", res.cycles / res.wall_time_s},
      {"sc_errors", res.sc_errors},
      {"threads", static_cast<long long>(std::max<std::size_t>(res.thread_cpu_s.size(), 1))},
  };
  add_timing_json(j, report, gt);
  add_validity_json(j, rec.map);
  rec.err.to_json(j, true);
  return j;
}

SimulationReport report(const Run& run) {
  const auto& [req, params, cfg, sc, res, gt, rec, wall_s] = run;
  SimulationReport r;
  r.headline =
      fmt::format("{} on scene '{}' ({}): {} frame access{}, {}, {}", params.sensor_id(), sc.name,
                  scene::shape_name(sc.shape), res.frames.size(), res.frames.size() == 1 ? "" : "es",
                  !req.kernel_only              ? "SystemC"
                  : res.thread_cpu_s.size() > 1 ? fmt::format("bare kernels on {} threads", res.thread_cpu_s.size())
                                                : "bare kernels",
                  req.noise_free ? "noise-free" : fmt::format("noise seed {}", req.seed));
  r.frame_label = "frame access";
  set_timing(r, gt, phases_json(run), res.frames.front().cycles, run.frame_time_s(), cfg.timing.beam_positions,
             rec.timing_matches);
  r.points_line = fmt::format("points visible {}, detected {}, missed {}, false {}", rec.visible, rec.detected,
                              rec.missed, rec.false_detections);
  r.error = rec.err, r.error_in_px = true;
  r.wall_time_s = wall_s;
  r.wall_note = fmt::format("{:.3g} simulated cycles/s", res.cycles / res.wall_time_s);
  return r;
}

SimulationResult simulate_ls_conventional(const SimulationRequest& req, const ParamSet& params, SimulationHost& host) {
  const auto t_start = Clock::now();
  const Checked c = check(req, params);
  const std::string vcd_base = host.open_trace();
  if (req.tick && !req.kernel_only)
    throw UserError(
        "--tick selects the kernel's cycle-by-cycle path; use it with --kernel-only (SystemC always ticks)");
  const scene::Scene sc = scene::ls_conventional_scene(scene::load_scene(req.scene, "ls-conventional"), params);
  fmt::print(stderr, "{}", scene::notes_text(sc.notes, "simulate"));
  const auto optics_ptr = std::make_shared<const scene::SceneOptics>(c.cfg, sc);
  const scene::SceneOptics& optics = *optics_ptr;
  // Per frame access and row: the centre, its points.csv line and the map's cells.
  host.check_memory(static_cast<double>(c.frames) * c.cfg.pixel.rows * 256.0,
                    fmt::format("{} frame accesses x {} rows", c.frames, c.cfg.pixel.rows), "--frames");
  host.open_output(sc.name);
  const auto res_ptr = std::make_shared<const SensorRunResult>(run_model(req, c.cfg, optics, c.frames, vcd_base, host));
  const SensorRunResult& res = *res_ptr;

  const golden::FrameTiming gt = golden::frame_timing(c.cfg.timing, c.cfg.multisampling.samplings);
  SimulationResult out;
  Reconstruction rec = map_cells(res, optics, c.cfg);
  rec.map.title = fmt::format("{} — {} ({} frame accesses)", sc.name, params.sensor_id(), res.frames.size());
  rec.map.x_label = "beam position (frame access)";
  // The map's files go out while its truth and the counts are worked out.
  rec.map_work = host.map_ready(rec.map);
  const CellTruths truths = map_truth(rec, res, optics, c.cfg.pixel.rows, req.points);
  host.truth_ready(rec.map);
  score(rec, truths, res_ptr, optics_ptr, c.cfg, gt, req.points);
  const Run run{req, params, c.cfg, sc, res, gt, rec, std::chrono::duration<double>(Clock::now() - t_start).count()};
  out.report = report(run);
  out.summary = summary(run, out.report);
  if (!sc.notes.empty()) out.summary["scene_notes"] = sc.notes;
  out.points = std::move(rec.points);
  out.frames_csv = std::move(rec.frames_csv);
  out.range_map = std::move(rec.map);
  out.map_work = std::move(rec.map_work);
  return out;
}

}  // namespace

const SimulateEntry& ls_conventional_simulate_entry() {
  static const SimulateEntry e{"ls-conventional", &simulate_ls_conventional, false, false, true, true, true};
  return e;
}

}  // namespace rangesim::systemc
