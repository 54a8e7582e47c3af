// rangesim simulate for tof-spad: the clock-level model (systemc/tof_spad/, bare kernels or the
// sc_module) on a tof-spad scene (scenes/tof-spad-*.toml, read here), the golden estimator on the
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
#include <toml++/toml.h>
#include <unistd.h>

#include "app/cli_common.h"
#include "app/cmd_simulate.h"
#include "app/output_dir.h"
#include "app/simulate/simulate_output.h"
#include "core/params.h"
#include "core/physics.h"
#include "core/tof_spad_config.h"
#include "core/user_error.h"
#include "golden/evaluate_sensor.h"
#include "systemc/tof_spad/tof_spad_sensor.h"

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

  double distance_at(int column) const { return shape == "step" && column >= step_column ? step_distance_m : distance_m; }
  PixelRates rates(int, int column) const {
    const double d = distance_at(column);
    const double r = reference_distance_m / d;
    return {signal_Hz * r * r, background_Hz, 2 * d / phys::kSpeedOfLight_m_per_s};
  }
};

double get_real(const toml::table& t, const std::string& file, const std::string& key, double def, double lo, double hi,
                const std::string& unit) {
  const auto node = t.at_path(key);
  if (!node) return def;
  const auto v = node.value<double>();
  if (!v || !std::isfinite(*v) || *v < lo || *v > hi)
    throw UserError(fmt::format("{}: {} = {}: allowed {:g} <= value <= {:g}{}", file, key,
                                v ? fmt::format("{:g}", *v) : "(not a number)", lo, hi, unit.empty() ? "" : " " + unit));
  return *v;
}

int get_int(const toml::table& t, const std::string& file, const std::string& key, int def, int lo, int hi) {
  const auto node = t.at_path(key);
  if (!node) return def;
  const auto v = node.value<long long>();
  if (!v || !node.is_integer() || *v < lo || *v > hi)
    throw UserError(fmt::format("{}: {}: allowed an integer {} <= value <= {}", file, key, lo, hi));
  return static_cast<int>(*v);
}

SpadScene load_spad_scene(const std::string& path, const TofSpadConfig& cfg, int array_rows, int array_columns) {
  toml::table t;
  try {
    t = toml::parse_file(path);
  } catch (const toml::parse_error& e) {
    throw UserError(fmt::format("{}: not a valid scene file: {}", path, e.description()));
  } catch (const std::exception& e) {
    throw UserError(fmt::format("--scene {}: cannot read: {}", path, e.what()));
  }
  // Only the keys of a tof-spad scene (an ls-conventional scene is refused, not misread).
  static const std::vector<std::pair<std::string, std::vector<std::string>>> allowed = {
      {"scene", {"name", "description"}},
      {"target", {"shape", "distance_m", "step_distance_m", "step_column"}},
      {"rates", {"signal_Hz", "reference_distance_m", "background_Hz"}},
      {"window", {"first_row", "rows", "first_column", "columns"}}};
  for (const auto& [table, node] : t) {
    const auto it = std::find_if(allowed.begin(), allowed.end(), [&](const auto& a) { return a.first == table.str(); });
    if (it == allowed.end() || !node.is_table())
      throw UserError(fmt::format("{}: [{}] is not a tof-spad scene table; allowed: [scene], [target], [rates], [window] "
                                  "(see scenes/tof-spad-plane.toml)", path, table.str()));
    for (const auto& [key, value] : *node.as_table()) {
      (void)value;
      if (std::find(it->second.begin(), it->second.end(), std::string(key.str())) == it->second.end())
        throw UserError(fmt::format("{}: {}.{} is not a tof-spad scene key; allowed in [{}]: {}", path, table.str(), key.str(),
                                    table.str(), fmt::join(it->second, ", ")));
    }
  }
  SpadScene s;
  s.file = path;
  s.name = t.at_path("scene.name").value_or(fs::path(path).stem().string());
  s.description = t.at_path("scene.description").value_or(std::string{});
  if (!t.at_path("target.distance_m"))
    throw UserError(fmt::format("{}: target.distance_m is required (tof-spad scene; see scenes/tof-spad-plane.toml)", path));
  s.shape = t.at_path("target.shape").value_or(std::string("plane"));
  if (s.shape != "plane" && s.shape != "step")
    throw UserError(fmt::format("{}: target.shape = \"{}\": allowed \"plane\", \"step\"", path, s.shape));
  // Echo (with +-6 sigma of the pulse) inside the TDC range and the laser period.
  const double period_s = 1.0 / cfg.laser.repetition_rate_Hz;
  const double max_m = 0.5 * phys::kSpeedOfLight_m_per_s * (std::min(period_s, cfg.tdc.full_range_s) - 2e-9);
  s.distance_m = get_real(t, path, "target.distance_m", s.distance_m, 0.3, max_m, "m");
  s.step_distance_m = get_real(t, path, "target.step_distance_m", s.distance_m, 0.3, max_m, "m");
  s.step_column = get_int(t, path, "target.step_column", array_columns / 2, 0, array_columns);
  s.signal_Hz = get_real(t, path, "rates.signal_Hz", s.signal_Hz, 0, 5e7, "counts/s");
  s.reference_distance_m = get_real(t, path, "rates.reference_distance_m", s.distance_m, 0.1, 1e3, "m");
  s.background_Hz = get_real(t, path, "rates.background_Hz", s.background_Hz, 0, 1e9, "counts/s");
  const int cpt = cfg.tdc.columns_per_tdc;
  s.rows = get_int(t, path, "window.rows", std::min(4, array_rows), 1, array_rows);
  s.first_row = get_int(t, path, "window.first_row", (array_rows - s.rows) / 2, 0, array_rows - s.rows);
  s.columns = get_int(t, path, "window.columns", std::min(16, array_columns), cpt, array_columns);
  if (s.columns % cpt != 0)
    throw UserError(fmt::format("{}: window.columns = {}: allowed a multiple of tdc.columns_per_tdc = {}", path, s.columns, cpt));
  const int default_first = ((array_columns - s.columns) / 2) / cpt * cpt;
  s.first_column = get_int(t, path, "window.first_column", default_first, 0, array_columns - s.columns);
  if (s.first_column % cpt != 0)
    throw UserError(fmt::format("{}: window.first_column = {}: allowed a multiple of tdc.columns_per_tdc = {} (TDC group edge)",
                                path, s.first_column, cpt));
  return s;
}

}  // namespace

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
  if (!opt.trace.empty()) {
    if (opt.kernel_only) throw UserError("--trace needs the SystemC model; drop --kernel-only (the bare kernels have no waveform)");
    if (opt.trace.size() < 5 || opt.trace.substr(opt.trace.size() - 4) != ".vcd")
      throw UserError(fmt::format("--trace {}: the waveform file name must end in .vcd", opt.trace));
    const fs::path parent = fs::absolute(opt.trace).parent_path();
    if (!fs::is_directory(parent) || ::access(parent.c_str(), W_OK) != 0)
      throw UserError(fmt::format("--trace {}: directory {} does not exist or is not writable", opt.trace, parent.string()));
  }
  SpadScene sc = load_spad_scene(opt.scene, cfg, array_rows, array_columns);
  if (opt.dense) sc.first_row = 0, sc.rows = array_rows, sc.first_column = 0, sc.columns = array_columns;
  OutputDir out(opt.out.empty() ? "rangesim-out/simulate/" + sc.name : opt.out, "--out");

  systemc::spad::TofSpadKernelOptions kopt;
  kopt.seed = opt.seed;
  kopt.event_skipping = !opt.tick;  // per clock: every TDC cycle evaluated (identical histograms, tested)
  if (opt.noise_free) kopt.noise = systemc::spad::SpadNoise::none();
  const systemc::spad::TofSpadKernel kernel(cfg, array_rows, array_columns, kopt);
  systemc::spad::PixelSelection sel;
  for (int r = sc.first_row; r < sc.first_row + sc.rows; ++r) sel.rows.push_back(r);
  sel.first_group = sc.first_column / cfg.tdc.columns_per_tdc;
  sel.groups = sc.columns / cfg.tdc.columns_per_tdc;
  const systemc::spad::RateSource rates = [&sc](int r, int c) { return sc.rates(r, c); };

  const std::string vcd_tmp_base = opt.trace.empty() ? "" : fmt::format("{}.partial-{}", opt.trace, ::getpid());
  const auto t_sim = Clock::now();
  systemc::spad::SystemcRun res;
  try {
    res = opt.kernel_only ? systemc::spad::run_tof_spad_kernel(kernel, sel, rates, frames)
                          : systemc::spad::run_tof_spad_systemc(kernel, sel, rates, frames, vcd_tmp_base);
  } catch (...) {
    if (!vcd_tmp_base.empty()) std::remove((vcd_tmp_base + ".vcd").c_str());
    throw;
  }
  const double sim_wall_s = std::chrono::duration<double>(Clock::now() - t_sim).count();
  if (res.sc_errors > 0) {
    if (!vcd_tmp_base.empty()) std::remove((vcd_tmp_base + ".vcd").c_str());
    throw std::runtime_error(fmt::format("the model reported {} SystemC error(s): see the messages above", res.sc_errors));
  }

  // ---- Range map and error against the ground truth ----
  const golden::FrameTiming gt = golden::frame_timing_tof_spad(params);
  std::vector<std::vector<double>> sum(static_cast<size_t>(sc.rows), std::vector<double>(static_cast<size_t>(sc.columns), 0.0));
  std::vector<std::vector<int>> cnt(static_cast<size_t>(sc.rows), std::vector<int>(static_cast<size_t>(sc.columns), 0));
  long long points_total = 0, detected = 0, photons = 0, avalanches = 0;
  double sum_sq = 0, sum_err = 0, max_abs = 0;
  bool timing_matches = true;
  std::string points = "frame,row,column,truth_range_m,detected,range_m,error_m,events\n";
  std::string frames_csv = "frame,cycles,laser_cycles,histogram_readout,avalanches,photons\n";
  for (const auto& f : res.frames) {
    frames_csv += fmt::format("{},{},{},{},{},{}\n", f.frame, f.cycles, f.phase_cycles[0], f.phase_cycles[1], f.avalanches, f.photons);
    timing_matches = timing_matches && f.cycles == gt.frame_cycles && f.phase_cycles[0] == gt.phases[0].cycles &&
                     f.phase_cycles[1] == gt.phases[1].cycles;
    photons += f.photons, avalanches += f.avalanches;
    for (const auto& p : f.pixels) {
      const double truth = sc.distance_at(p.column);
      long long ev = 0;
      for (long long e : p.events) ev += e;
      ++points_total;
      double err = NAN;
      if (p.time_s) {
        ++detected;
        err = p.range_m - truth;
        sum_sq += err * err, sum_err += err, max_abs = std::max(max_abs, std::fabs(err));
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
  const double rms = detected ? std::sqrt(sum_sq / detected) : NAN, mean_err = detected ? sum_err / detected : NAN;

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
      {"range_error_rms_m", json_number(rms)},
      {"range_error_mean_m", json_number(mean_err)},
      {"range_error_max_abs_m", detected ? nlohmann::json(max_abs) : nlohmann::json(nullptr)},
      {"points", points_total},
      {"points_detected", detected},
      {"pixels_simulated", sc.rows * sc.columns},
      {"photons_simulated", photons},
      {"avalanches_simulated", avalanches},
      {"wall_time_s", wall_s},
      {"simulation_wall_time_s", sim_wall_s},
      {"photons_per_s", static_cast<double>(photons) / sim_wall_s},
      {"sc_errors", res.sc_errors},
  };
  out.write("range_map.csv", range_csv);
  out.write("points.csv", points);
  out.write("frames.csv", frames_csv);
  std::string warning;
  if (!opt.no_plots) warning = render_range_map(out, map, fmt::format("{} — tof-spad ({} frame{})", sc.name, res.frames.size(), res.frames.size() == 1 ? "" : "s"),
                                                   "column in window", "row in window");
  if (!warning.empty()) j["warnings"] = {warning};
  out.write("summary.json", j.dump(2) + "\n");
  const std::vector<std::string> written = out.commit();
  if (!vcd_tmp_base.empty()) fs::rename(vcd_tmp_base + ".vcd", opt.trace);

  if (opt.json) {
    fmt::print("{}\n", j.dump(2));
    return kExitOk;
  }
  if (!warning.empty()) fmt::print(stderr, "rangesim: warning: {}\n", warning);
  fmt::print("tof-spad on scene '{}' ({}): {} frame{}, {}, {}, window {} rows x {} columns\n\n", sc.name, sc.shape,
             res.frames.size(), res.frames.size() == 1 ? "" : "s", opt.kernel_only ? "bare kernels" : "SystemC",
             opt.noise_free ? "noise-free" : fmt::format("noise seed {}", opt.seed), sc.rows, sc.columns);
  fmt::print("  {:<18} {:>14} {:>14} {:>12}\n", "phase", "cycles", "golden", "time");
  for (const auto& p : phases)
    fmt::print("  {:<18} {:>14} {:>14} {:>9.3f} ms\n", p["name"].get<std::string>(), p["cycles"].get<long long>(),
               p["golden_cycles"].get<long long>(), p["time_s"].get<double>() * 1e3);
  fmt::print("  {:<18} {:>14} {:>14}\n\n", "frame", first.cycles, gt.frame_cycles);
  fmt::print("  frame time    {:>10.4f} s measured, {:.4f} s golden{}\n", frame_time_s, gt.frame_time_s,
             timing_matches ? "" : "  (MISMATCH)");
  fmt::print("  frame rate    {:>10.4f} Hz measured, {:.4f} Hz golden\n\n", frame_rate_Hz, gt.frame_access_rate_Hz);
  fmt::print("  pixels {} x {} frames, detected {}\n", sc.rows * sc.columns, res.frames.size(), detected);
  if (detected)
    fmt::print("  range error   rms {:.3f} mm, mean {:+.3f} mm, max |e| {:.3f} mm\n", rms * 1e3, mean_err * 1e3, max_abs * 1e3);
  fmt::print("  wall time     {:.2f} s, {:.3g} photons/s simulated\n\n", wall_s, static_cast<double>(photons) / sim_wall_s);
  for (const auto& w : written) fmt::print("  wrote {}\n", w);
  if (!opt.trace.empty()) fmt::print("  wrote {}\n", opt.trace);
  return kExitOk;
}

}  // namespace rangesim::app
