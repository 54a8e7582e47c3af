// rangesim command line: the subcommands, their options and --help texts (CLI11).
#include "app/cli_parse.h"

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <ostream>

#include "app/cli_checks.h"
#include "app/cli_common.h"
#include "core/sensor_registry.h"

namespace rangesim::app {

namespace {

// "V (ls-conventional), A (ls-demodulation, tof-lockin), ..." from the registered schemas: the
// unit is the suffix of each sensor's evaluation.signal_min_<unit> key.
std::string signal_units() {
  std::vector<std::pair<std::string, std::string>> units;  // unit, sensors
  for (const auto& s : sensors())
    for (const auto& p : s.schema().params) {
      const std::string prefix = "evaluation.signal_min_";
      if (p.key.rfind(prefix, 0) != 0) continue;
      const std::string unit = p.key.substr(prefix.size());
      auto it = std::find_if(units.begin(), units.end(), [&](const auto& u) { return u.first == unit; });
      if (it == units.end())
        units.push_back({unit, s.id});
      else
        it->second += ", " + s.id;
    }
  std::string text;
  for (const auto& [unit, ids] : units) text += (text.empty() ? "" : ", ") + unit + " (" + ids + ")";
  return text;
}

}  // namespace

namespace {

// Validators run on the flag's text before CLI11 converts it (app/cli_checks.h); an empty
// description keeps --help as it is.
CLI::Validator integer_in(long long lo, long long hi) {
  return CLI::Validator([lo, hi](std::string& s) { return check_integer_text(s, lo, hi); }, "");
}
CLI::Validator unsigned_in(std::uint64_t lo, std::uint64_t hi) {
  return CLI::Validator([lo, hi](std::string& s) { return check_unsigned_text(s, lo, hi); }, "");
}
CLI::Validator real_in(double lo, bool lo_exclusive, double hi, const std::string& unit) {
  return CLI::Validator([=](std::string& s) { return check_real_text(s, lo, lo_exclusive, hi, unit); }, "");
}
const CLI::Validator kPath(check_path_text, "");
constexpr std::uint64_t kMaxU64 = std::numeric_limits<std::uint64_t>::max();

// Any integer passes here, so that the check made where the value is used names its key and the
// sensor's range; text that is not one (or beyond 64 bits) is refused with the range [lo, hi].
std::string any_integer(std::string& s, long long lo, long long hi) {
  std::string wide = s;
  if (!check_integer_text(wide, std::numeric_limits<long long>::min(), std::numeric_limits<long long>::max()).empty())
    return check_integer_text(s, lo, hi);
  s = wide;
  return "";
}

// One item of --trace-pixels, ROW:COLUMN with non-negative integers (the run checks its window).
systemc::TracePixel trace_pixel(const std::string& item) {
  const std::size_t colon = item.find(':');
  std::string row = item.substr(0, colon), column = colon == std::string::npos ? "" : item.substr(colon + 1);
  const std::string bad_row = check_integer_text(row, 0, 1000000000),
                    bad_column = check_integer_text(column, 0, 1000000000);
  if (colon == std::string::npos || !bad_row.empty() || !bad_column.empty())
    throw CLI::ValidationError("--trace-pixels",
                               "'" + item + "' is not ROW:COLUMN with integers 0..1000000000 (e.g. 3:17)");
  return {std::stoi(row), std::stoi(column)};
}

// A flag that sets a preset key (--samplings, --adc-bits, --frames): any_integer, with the widest
// range of the keys ending in `suffix` over the registered sensors.
CLI::Validator schema_integer(const std::string& suffix) {
  return CLI::Validator(
      [suffix](std::string& s) {
        double lo = 0, hi = -1;
        for (const auto& sensor : sensors())
          for (const auto& p : sensor.schema().params)
            if (p.kind == ParamKind::Integer && p.key.size() >= suffix.size() &&
                p.key.compare(p.key.size() - suffix.size(), suffix.size(), suffix) == 0) {
              const double a = p.min_exclusive ? p.min + 1 : p.min;
              lo = hi < lo ? a : std::min(lo, a), hi = std::max(hi, p.max);
            }
        if (hi < lo) lo = std::numeric_limits<int>::min(), hi = std::numeric_limits<int>::max();
        return any_integer(s, static_cast<long long>(lo), static_cast<long long>(hi));
      },
      "");
}

// --max-memory of a long command: its resident size is watched and the run refused up front when
// its estimate exceeds it (app/run_control.h).
void add_max_memory(CLI::App* sub, ParsedCommand& c) {
  sub->add_option("--max-memory", c.max_memory,
                  "Memory budget, e.g. 512M or 2G (16M..1024T): a run whose estimate exceeds it is refused up\n"
                  "front, one that grows beyond it ends writing nothing (exit 4); default: the memory available")
      ->check(CLI::Validator(
          [](std::string& s) {
            std::uint64_t bytes = 0;
            return check_memory_text(s, bytes);
          },
          ""));
}

void add_budgets(CLI::App* sub, ParsedCommand& c) {
  sub->add_option("--max-seconds", c.max_seconds,
                  "Wall-time budget of the command: when exceeded the run ends writing nothing and exits 4\n"
                  "(a sweep keeps its journal and prints how to resume)")
      ->check(real_in(0, true, 1e9, "s"));
  add_max_memory(sub, c);
}

}  // namespace

CommandLine parse_command_line(int argc, const char* const* argv, std::ostream& out, std::ostream& err) {
  CLI::App app{
      "rangesim: cycle-accurate simulator of 3-D range-finding smart image sensors.\n"
      "Sensors (presets): " +
          sensor_ids() +
          "; a path to a\n"
          "preset .toml file works wherever a sensor is expected, and --set KEY=VALUE changes it.\n"
          "Exit codes: 0 ok, 1 internal error, 2 bad input (preset, flag, output directory),\n"
          "3 sensor not modelled yet for the command, 4 a budget ran out (--max-seconds, --max-memory) or\n"
          "cosim found mismatches, 128 + the signal when stopped by one (130 Ctrl-C, 143 SIGTERM, 129 SIGHUP);\n"
          "a journaled sweep (evaluate --trials, sweep, bench, cosim all) keeps its journal and prints the\n"
          "command that resumes. An output folder has one writer at a time; another command's results in it\n"
          "are replaced only with --force.",
      "rangesim"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "rangesim 0.1.0");

  CommandLine result;
  ParsedCommand& c = result.command;

  ListOptions& list_opt = c.list;
  auto* list = app.add_subcommand("list", "List the sensor presets and which commands model them");
  list->add_flag("--json", list_opt.json, "Print JSON");

  ShowOptions& show_opt = c.show;
  auto* show =
      app.add_subcommand("show", "Show a preset's resolved parameters with units, sources and the file each came from");
  show->add_option("preset", show_opt.preset, "Preset id or path to a .toml file")->required();
  show->add_flag("--json", show_opt.json, "Print JSON");
  show->add_option("--set", show_opt.settings,
                   "Set a parameter after the preset, KEY=VALUE (repeatable), e.g. --set "
                   "timing.clock_Hz=50e6;\nchecked like a preset value (`rangesim show <sensor>` lists the keys)")
      ->type_name("KEY=VALUE");

  EvaluateOptions& ev_opt = c.evaluate;
  auto* ev = app.add_subcommand(
      "evaluate",
      "Background-light and range-accuracy evaluation over a signal x background grid (thesis ch. 3):\n"
      "detectable area with reasons, accuracy map, SBR' both ways, dynamic ranges, 1-D sweeps. Writes CSV\n"
      "maps, summary.json, heat maps and line plots (PNG, SVG) into --out.");
  ev->add_option("sensor", ev_opt.sensor, "Preset id or path to a .toml file")->required();
  ev->add_option("--set", ev_opt.settings,
                 "Set a parameter after the preset, KEY=VALUE (repeatable), e.g. --set timing.clock_Hz=50e6;\nchecked "
                 "like a preset value (`rangesim show <sensor>` lists the keys)")
      ->type_name("KEY=VALUE");
  ev->add_option("--signal", ev_opt.signal,
                 "Signal grid LO:HI:N, log-spaced, in the sensor's unit: " + signal_units() + " (default: preset)");
  ev->add_option("--background", ev_opt.background, "Background grid LO:HI:N, same unit as --signal (default: preset)");
  ev->add_option("--background-lux", ev_opt.background_lux,
                 "Background grid LO:HI:N in lux of ambient light at the target (log-spaced), turned into the\n"
                 "sensor's unit by its radiometry under --scene (docs/radiometry.md); instead of --background")
      ->type_name("LO:HI:N");
  ev->add_option("--signal-power", ev_opt.signal_power,
                 "Signal grid LO:HI:N in watts of mean source power (log-spaced), at the scene's distance, turned\n"
                 "into the sensor's unit by its radiometry under --scene; instead of --signal")
      ->type_name("LO:HI:N");
  ev->add_option("--scene", ev_opt.scene,
                 "Physical scene of --background-lux / --signal-power: reflectance, spectrum, filter, beam,\n"
                 "distance (default: the built-in sunlit-wall, scenes/sunlit-wall.toml)")
      ->check(kPath);
  ev->add_option("--samplings", ev_opt.samplings, "Samplings per integration (default: preset)")
      ->transform(schema_integer("multisampling.samplings"));
  ev->add_option("--adc-bits", ev_opt.adc_bits,
                 "ADC bits, the preset's *.adc_bits (per sampling where the sensor samples several times; 1 = "
                 "comparator) (default: preset)")
      ->transform(schema_integer(".adc_bits"));
  ev->add_option("--frames", ev_opt.frames, "Frames averaged, where the sensor has that parameter (default: preset)")
      ->transform(schema_integer("evaluation.frames_averaged"));
  ev->add_option("--out", ev_opt.out, "Output directory (default: rangesim-out/<sensor>)")->check(kPath);
  ev->add_flag("--force", ev_opt.force,
               "Replace the results of another kind of run in --out (its rangesim files go; other files stay)");
  add_max_memory(ev, c);
  ev->add_flag("--json", ev_opt.json, "Print summary.json to stdout instead of the table");
  ev->add_flag("--no-plots", ev_opt.no_plots, "Skip the PNG/SVG heat maps");
  // Monte Carlo evaluation (app/montecarlo/, docs/evaluate-montecarlo.md).
  ev->add_option("--trials", ev_opt.trials,
                 "Monte Carlo: run the clock-level kernels with noise N times at every detectable grid point\n"
                 "(2..10000000) and report every accuracy value with its 95% confidence interval (mc_points.csv,\n"
                 "mc_*.csv maps, mc_accuracy.png, summary.json monte_carlo); every quantity where golden (accuracy,\n"
                 "without outliers where it splits them off, P(detect), P(outlier)) falls outside the interval is\n"
                 "printed and listed in mc_golden_outside_ci.csv")
      ->transform(integer_in(2, 10000000));
  ev->add_option("--target-error", ev_opt.target_error,
                 "Monte Carlo: add trials per point until the 95% CI half-width of the accuracy is <= E metres\n"
                 "(starts with --trials, default 100; stops at --max-trials with a warning)")
      ->check(real_in(0, true, 1e6, "m"));
  ev->add_option("--max-trials", ev_opt.max_trials, "Monte Carlo: trial budget per point (default 100000)")
      ->transform(integer_in(2, 1000000000));
  ev->add_option("--threads", ev_opt.threads,
                 "Monte Carlo: worker threads, 1..1024 (default: all cores); results are bit-identical for any count")
      ->transform(integer_in(1, 1024));
  ev->add_option("--seed", ev_opt.seed, "Monte Carlo: key of the random streams, 0..2^64-1 (default 1)")
      ->transform(unsigned_in(0, kMaxU64));
  ev->add_option("--max-seconds", ev_opt.max_seconds,
                 "Wall-time budget of the command: when exceeded the run ends writing nothing and exits 4 (a\n"
                 "grid that would take longer is refused once its pace is known); Monte Carlo: the sweep stops,\n"
                 "keeps its journal and exits 4")
      ->check(real_in(0, true, 1e9, "s"));
  ev->add_flag("--resume", ev_opt.resume,
               "Monte Carlo: continue the interrupted sweep whose journal is in --out (same options required);\n"
               "the output is byte-identical to an uninterrupted run. Exit codes: 130, 143, 129 stopped by Ctrl-C,\n"
               "SIGTERM, SIGHUP; 4 a budget ran out");

  FrameRateOptions& fr_opt = c.frame_rate;
  auto* fr = app.add_subcommand("frame-rate", "Frame time from the clock schedule, by phase, and the rates");
  fr->add_option("sensor", fr_opt.sensor, "Preset id or path to a .toml file")->required();
  fr->add_option("--samplings", fr_opt.samplings, "Samplings per frame access (default: preset)")
      ->transform(schema_integer("multisampling.samplings"));
  fr->add_flag("--json", fr_opt.json, "Print JSON");
  fr->add_option("--set", fr_opt.settings,
                 "Set a parameter after the preset, KEY=VALUE (repeatable), e.g. --set timing.clock_Hz=50e6;\nchecked "
                 "like a preset value (`rangesim show <sensor>` lists the keys)")
      ->type_name("KEY=VALUE");

  SimulateOptions& sim_opt = c.simulate;
  auto* sim = app.add_subcommand(
      "simulate",
      "Clock-level model of the sensor (SystemC, or the bare cycle kernels) on a scene: range map with its\n"
      "error against the scene's ground truth, per-frame cycle counts by phase and the frame rate measured\n"
      "from simulated time beside the clock schedule. Each pixel's range is valid or not by the sensor's rule\n"
      "(preset keys; summary.json names it): invalid pixels are blank. Writes range_map.csv/.png,\n"
      "range_error.png, confidence_map.csv, points.csv, frames.csv and summary.json (valid_fraction,\n"
      "false_valid_fraction) into --out.");
  sim->add_option("sensor", sim_opt.sensor, "Preset id or path to a .toml file")->required();
  sim->add_option("--scene", sim_opt.scene,
                  "Scene file (TOML; examples in scenes/, docs/simulate.md): every sensor takes every scene, the\n"
                  "light in lux and watts through its radiometry (docs/radiometry.md); keys it cannot use are notes;\n"
                  "target.shape = \"depth_map\" reads a PGM/PFM depth image (scenes/*depth-map.toml)")
      ->required();
  sim->add_option("--frames", sim_opt.frames,
                  "Frame accesses to simulate (default: one range map = timing.beam_positions)")
      ->transform(CLI::Validator([](std::string& s) { return any_integer(s, 1, 1000000); }, ""));
  sim->add_option("--seed", sim_opt.seed, "Seed of the noise streams, 0..2^64-1 (default: 1)")
      ->transform(unsigned_in(0, kMaxU64));
  sim->add_option("--set", sim_opt.settings,
                  "Set a parameter after the preset, KEY=VALUE (repeatable), checked like a preset value")
      ->type_name("KEY=VALUE");
  sim->add_option("--trace", sim_opt.trace,
                  "Write the waveform of the SystemC run to FILE.vcd, or FILE.fst (converted with vcd2fst from the "
                  "gtkwave package); off by default")
      ->check(kPath);
  sim->add_option("--trace-rows", sim_opt.trace_rows,
                  "With --trace: the rows whose blocks (address search, centre processor) the waveform shows, e.g.\n"
                  "0,5,9 (default: first, quarter, middle, last); sensors without per-row blocks refuse it")
      ->delimiter(',')
      ->type_name("LIST");
  sim->add_option_function<std::vector<std::string>>(
         "--trace-pixels",
         [&sim_opt](const std::vector<std::string>& items) {
           for (const std::string& item : items) sim_opt.trace_pixels.push_back(trace_pixel(item));
         },
         "With --trace: the pixels whose signals the waveform shows, ROW:COLUMN of the pixel array, e.g.\n"
         "0:5,10:7 (default: the sensor's choice, see docs/simulate.md)")
      ->delimiter(',')
      ->type_name("LIST");
  sim->add_option("--out", sim_opt.out, "Output directory (default: rangesim-out/simulate/<scene name>)")->check(kPath);
  sim->add_flag("--force", sim_opt.force,
                "Replace the results of another kind of run in --out (its rangesim files go; other files stay)");
  add_budgets(sim, c);
  sim->add_flag("--json", sim_opt.json, "Print summary.json to stdout instead of the table");
  sim->add_flag("--kernel-only", sim_opt.kernel_only, "Run the bare C++ cycle kernels, no SystemC elaboration");
  sim->add_flag("--tick,--no-event-skip", sim_opt.tick,
                "With --kernel-only: evaluate every clock cycle (event skipping off)");
  sim->add_flag("--noise-free", sim_opt.noise_free, "Switch all noise sources off");
  sim->add_flag("--dense,--no-sparse", sim_opt.dense,
                "Simulate every pixel one by one (sparse pixels off: no window around the beam, background-only "
                "pixels not drawn as one class)");
  sim->add_flag("--no-aggregate", sim_opt.no_aggregate,
                "Run the periods or laser cycles the sensor's model aggregates (correlation periods, accumulation\n"
                "periods, laser cycles: docs/simulate.md) one by one instead of in one exact jump or draw;\n"
                "a sensor without aggregation refuses it");
  sim->add_option("--threads", sim_opt.threads,
                  "With --kernel-only: threads the kernel runs on, 1..1024 (default: all cores), each with\n"
                  "consecutive frame accesses; the results are bit-identical for any count. ls-conventional;\n"
                  "the other sensors' kernels run on one thread and refuse more. The output files are written\n"
                  "side by side on as many threads (every sensor: all cores unless --threads is given)")
      ->transform(integer_in(1, 1024));
  sim->add_flag("--no-plots", sim_opt.no_plots, "Skip range_map.png and range_error.png");
  sim->add_flag("--points", sim_opt.points,
                "Also write the per-point table, points.npy or points.csv: per frame and row (tof-spad: per\n"
                "pixel; tof-lockin has none) the truth, the detection, the range, its error and validity.\n"
                "Off by default: a full ls-conventional map's table is 9.6 MB, four times both maps");
  auto* csv_flag =
      sim->add_flag("--csv", sim_opt.csv,
                    "Write range_map, confidence_map and points (--points) as CSV. Default: a table of more than\n"
                    "100,000 numbers as NumPy .npy (numpy.load; range_map.npy a float64 matrix, NaN = no range;\n"
                    "points.npy a record array with the CSV's columns as fields: indices int32, flags bool,\n"
                    "counts int64, the rest float64), smaller ones as CSV; frames.csv is always CSV");
  sim->add_flag("--npy", sim_opt.npy,
                "Write range_map, confidence_map and points (--points) as NumPy .npy, small ones too")
      ->excludes(csv_flag);
  sim->add_option("--time-step", sim_opt.time_step_s,
                  "Integrate the received pulse's overlap with the gate windows numerically at this step in\n"
                  "seconds (midpoint rule; allowed T0 / 1e5 .. T0) instead of in closed form; 0 (default) = exact.\n"
                  "Error falls and cost rises as the step shrinks; sensors exact on their clock grid refuse it")
      ->check(CLI::Validator(
          [](std::string& s) {
            // Any number passes: the model's check names the range of its preset (T0 / 1e5 .. T0).
            char* end = nullptr;
            std::strtod(s.c_str(), &end);
            return !s.empty() && *end == '\0' ? std::string()
                                              : "'" + s +
                                                    "' is not a number; allowed 0 (exact) or a step in seconds "
                                                    "from source.pulse_width_s / 1e5 to source.pulse_width_s";
          },
          ""));

  CompareOptions& cmp_opt = c.compare;
  auto* cmp = app.add_subcommand(
      "compare",
      "The sensors side by side on one physical scene and one light axis (thesis Fig. 1.4 and Table 5.1):\n"
      "each sensor's radiometry turns lux of ambient light and watts of source power into its own unit and its\n"
      "golden model evaluates the grid. Writes report.html (self-contained), compare.json, compare.csv (Table\n"
      "5.1 in physical units), sbr_vs_background.csv, accuracy_vs_background.csv and the plots\n"
      "fig1_4_sbr_vs_background.{png,svg} and accuracy_vs_background.{png,svg} into --out.");
  cmp->add_option("sensors", cmp_opt.sensors,
                  "Sensors to compare: preset ids or paths to .toml files (default: every registered sensor)");
  cmp->add_option(
         "--scene", cmp_opt.scene,
         "Physical scene (TOML with [ambient] and [source], docs/radiometry.md); default: the built-in\n"
         "sunlit-wall (scenes/sunlit-wall.toml: 50% wall at 1 m, 10 klux sunlight, 1 W at 850 nm, 10 nm filter)")
      ->check(kPath);
  cmp->add_option("--background-lux", cmp_opt.background_lux,
                  "Background axis LO:HI:N, lux of ambient light at the target, log-spaced (default 0.1:1e7:41)")
      ->type_name("LO:HI:N");
  cmp->add_option("--signal-power", cmp_opt.signal_power,
                  "Signal axis LO:HI:N, watts of mean source power, log-spaced (default 1e-4:10:26)")
      ->type_name("LO:HI:N");
  cmp->add_option("--out", cmp_opt.out, "Output directory (default: rangesim-out/compare)")->check(kPath);
  cmp->add_flag("--force", cmp_opt.force,
                "Replace the results of another kind of run in --out (its rangesim files go; other files stay)");
  cmp->add_flag("--json", cmp_opt.json, "Print compare.json to stdout instead of the table");
  cmp->add_flag("--no-plots", cmp_opt.no_plots, "Skip the plots (report.html then has the tables only)");
  add_budgets(cmp, c);

  TableOptions& tb_opt = c.table;
  auto* tb = app.add_subcommand(
      "table",
      "Thesis Table 5.1 for the four seed sensors beside rangesim's values (thesis value, ours, difference,\n"
      "and why they differ), plus the chips' published figures with their status");
  tb->add_flag("--json", tb_opt.json, "Print JSON (table and published figures)");
  tb->add_flag("--published", tb_opt.published, "Also list the published figures on the terminal");
  tb->add_option("--out", tb_opt.out,
                 "Also write table5_1.{md,html,csv,json} and published_figures.csv into this directory")
      ->check(kPath);
  tb->add_flag("--force", tb_opt.force,
               "Replace the results of another kind of run in --out (its rangesim files go; other files stay)");
  add_budgets(tb, c);

  BenchOptions& bench_opt = c.bench;
  auto* bench = app.add_subcommand(
      "bench",
      "Run time against error for each sensor (every fidelity setting of `simulate`: harness, event skipping,\n"
      "sparse pixels, aggregation, noise, frames; plus the verilated RTL readout) as a table and a Pareto plot,\n"
      "and the throughput ratios (sparse_vs_dense, model_vs_rtl, floor_ratio, systemc_vs_kernel, realtime_factor,\n"
      "output_share, mc_vs_bare_rng, aggregated_vs_per_clock_lockin/_spad/_demod, sparse_vs_dense_spad,\n"
      "threads2_vs_1, numpy_peer_ls_conventional, numpy_peer_lockin_mc), each measured in one run beside its\n"
      "target with a met flag; the missed targets are printed last. Writes bench.json, figures.md,\n"
      "pareto.md/.csv/.png/.svg into --out.\n"
      "Exit code 1 if an identity check inside the bench failed (speed targets are reported, not enforced).\n"
      "docs/bench.md explains every figure.");
  bench->add_flag("--quick", bench_opt.quick,
                  "Fewer frames for the slow references: the same keys in under two minutes");
  bench->add_flag("--json", bench_opt.json, "Print bench.json to stdout instead of the tables");
  bench->add_option("--out", bench_opt.out, "Output directory (default: rangesim-out/bench)")->check(kPath);
  bench->add_flag("--force", bench_opt.force,
                  "Replace the results of another kind of run in --out (its rangesim files go; other files stay)");
  add_budgets(bench, c);
  bench->add_flag("--resume", bench_opt.resume,
                  "Continue a killed or interrupted bench: every finished Pareto row and figure group is kept in a\n"
                  "journal under --out and not measured again");

  SweepOptions& sw_opt = c.sweep;
  auto* sw = app.add_subcommand(
      "sweep",
      "Architecture variants of one preset: for each, the clock-schedule frame and range-map rates and the\n"
      "evaluate summary (signal and background ranges, SBR', accuracy min and max over the preset's grid).\n"
      "Writes sweep.csv, sweep.json, pareto.png/.svg (range-map rate against worst accuracy, front marked)\n"
      "and <key>.png/.svg per varied key into --out. Invalid variants are rows with their reason. A killed\n"
      "sweep continues with --resume, identically; --shard K/N + `rangesim merge` split it across machines.");
  sw->add_option("sensor", sw_opt.sensor, "Preset id or path to a .toml file")->required();
  sw->add_option("--vary", sw_opt.vary,
                 "KEY=LO:HI:N (linear), KEY=LO:HI:N:log or KEY=v1,v2,... (repeatable; integer keys take the\n"
                 "nearest integers of a range); the variants are the cross product, first --vary outermost")
      ->type_name("KEY=SPEC")
      ->required();
  sw->add_flag("--zip", sw_opt.zip, "Take the i-th value of every --vary together instead of the cross product");
  sw->add_option("--set", sw_opt.settings, "Set a parameter of every variant, KEY=VALUE (repeatable)")
      ->type_name("KEY=VALUE");
  sw->add_option("--shard", sw_opt.shard,
                 "K/N: compute only the variants i with i mod N = K-1 and write sweep.shard-K-of-N.json\n"
                 "(batch arrays; `rangesim merge` combines the N shards into the unsharded output)");
  sw->add_option("--out", sw_opt.out, "Output directory (default: rangesim-out/sweep/<sensor>)")->check(kPath);
  sw->add_flag("--force", sw_opt.force,
               "Replace the results of another kind of run in --out (its rangesim files go; other files stay)");
  add_budgets(sw, c);
  sw->add_flag("--json", sw_opt.json, "Print sweep.json to stdout instead of the table");
  sw->add_flag("--no-plots", sw_opt.no_plots, "Skip the PNG/SVG plots");
  sw->add_flag("--resume", sw_opt.resume, "Continue the sweep whose journal is in --out (same options)");
  sw->add_option("--trials", sw_opt.trials,
                 "Also run the clock-level kernels with noise T times at every detectable grid point of each\n"
                 "variant (2..10000000): mc_accuracy_min/max_m with their 95% confidence intervals")
      ->transform(integer_in(2, 10000000));
  sw->add_option("--seed", sw_opt.seed, "Key of the Monte Carlo and co-simulation streams, 0..2^64-1 (default 1)")
      ->transform(unsigned_in(0, kMaxU64));
  sw->add_flag("--cosim", sw_opt.cosim,
               "Also co-simulate each variant's RTL (verilated at run time for its parameters, cached) against\n"
               "its clock-level model: cosim_transactions, cosim_mismatches");
  sw->add_option("--cosim-cycles", sw_opt.cosim_cycles, "Clock cycles of each --cosim run (default 20000)")
      ->transform(unsigned_in(1, 1000000000));
  sw->add_option("--pareto-accuracy", sw_opt.pareto_accuracy,
                 "The accuracy axis of the Pareto front: min (best over the detectable area, default) or max (worst)")
      ->check(CLI::IsMember({"min", "max"}));

  MergeOptions& mg_opt = c.merge;
  auto* mg = app.add_subcommand("merge",
                                "Combine the shards of one sweep (sweep --shard K/N) into the output of the unsharded\n"
                                "sweep; refuses shards of different sweeps, missing or repeated shards");
  mg->add_option("parts", mg_opt.parts, "The sweep.shard-K-of-N.json files")->required();
  mg->add_option("--out", mg_opt.out, "Output directory (default: rangesim-out/sweep/merged)")->check(kPath);
  mg->add_flag("--force", mg_opt.force,
               "Replace the results of another kind of run in --out (its rangesim files go; other files stay)");
  mg->add_flag("--json", mg_opt.json, "Print sweep.json to stdout instead of the table");
  mg->add_flag("--no-plots", mg_opt.no_plots, "Skip the PNG/SVG plots");
  mg->add_option("--pareto-accuracy", mg_opt.pareto_accuracy, "min (default) or max, as for sweep")
      ->check(CLI::IsMember({"min", "max"}));

  CosimCommandOptions& co_opt = c.cosim;
  auto* co = app.add_subcommand(
      "cosim",
      "Co-simulate RTL (verilated) against the clock-level model and, where exact, the golden model on\n"
      "random stimulus; report cycles, transactions, mismatches (frame, row, column, cycle, expected,\n"
      "actual) and RTL line/toggle coverage. Targets: a sensor, a block, or 'all' (see --list).\n"
      "A preset file (.toml) co-simulates the RTL of that preset's own architecture (every sensor;\n"
      "tof-lockin takes the preset's timing as run-time inputs): its Verilog parameters come from the\n"
      "preset, the RTL is verilated\n"
      "and compiled at run time (needs verilator) and cached in $RANGESIM_RTL_CACHE (default\n"
      "$XDG_CACHE_HOME/rangesim/rtl, else ~/.cache/rangesim/rtl).\n"
      "--rtl FILE.sv co-simulates your own Verilog instead: its modules replace the rangesim blocks of\n"
      "the same name inside the readout (ports as in docs/rtl-contract.md, checked first), same\n"
      "harness and scoreboard; with a sensor target it runs that target's instance, with a preset file\n"
      "that preset's architecture.\n"
      "Exit codes: 0 no mismatch, 4 mismatches found (or an injected fault not applied), 2 bad input,\n"
      "130 interrupted (Ctrl-C; 'all' keeps its journal and prints the command that resumes).");
  co->add_option("target", co_opt.target, "Target name (sensor id or RTL block), 'all', or a preset file (.toml)");
  co->add_option("--cycles", co_opt.cycles,
                 "Clock cycles to simulate, 1..1000000000, rounded up to whole transactions (default: 100000)")
      ->transform(unsigned_in(1, 1000000000));
  co->add_option("--set", co_opt.settings,
                 "With a preset: set a parameter after it, KEY=VALUE (repeatable), checked like a preset value")
      ->type_name("KEY=VALUE");
  co->add_option("--seed", co_opt.seed,
                 "Seed of the stimulus and of Verilator's random initial state, 0..2^64-1 (default: 1)")
      ->transform(unsigned_in(0, kMaxU64));
  co->add_option("--trace", co_opt.trace,
                 "Write a VCD of the RTL run, with the model's expected values beside it under the scope\n"
                 "'expected', to this file ('all': FILE_<target>.vcd), and beside it FILE.gtkw, a GTKWave\n"
                 "save file with each compared signal below its RTL counterpart")
      ->check(kPath);
  co->add_option("--junit", co_opt.junit,
                 "Write a JUnit XML report (one testcase per target and scoreboard check) to this file")
      ->check(kPath);
  co->add_option("--coverage-out", co_opt.coverage_out,
                 "Write the RTL coverage counters in Verilator's coverage.dat format to this file, for\n"
                 "verilator_coverage --annotate ('all': FILE_<target>.dat)")
      ->check(kPath);
  co->add_option("--rtl", co_opt.rtl,
                 "Your Verilog file (repeatable): its modules replace the rangesim blocks of the same name in a\n"
                 "sensor's readout (its target or a preset file; other targets refuse it, naming those allowed)")
      ->type_name("FILE.sv");
  co->add_option("--top", co_opt.top, "With --rtl: the block your files implement (default: every block they define)");
  co->add_option(
      "--inject-fault", co_opt.inject_fault,
      "Run with this named fault of the target (see --list; a preset takes its sensor's); it must be reported");
  co->add_flag("--json", co_opt.json,
               "Print JSON (keys cycles, transactions, mismatches, coverage_line, coverage_toggle, ...)");
  co->add_flag("--list", co_opt.list, "List the targets and their faults");
  co->add_option(
      "--journal", co_opt.journal,
      "'all': journal of the finished targets (default: rangesim-out/cosim/all.journal; removed on completion)");
  co->add_flag("--resume", co_opt.resume,
               "'all': continue a killed or interrupted run from its journal (same options); the report equals an\n"
               "uninterrupted run's apart from wall times");
  add_budgets(co, c);

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    result.finished = true;
    result.exit_code = app.exit(e, out, err);
    return result;
  } catch (const CLI::CallForAllHelp& e) {
    result.finished = true;
    result.exit_code = app.exit(e, out, err);
    return result;
  } catch (const CLI::CallForVersion& e) {
    result.finished = true;
    result.exit_code = app.exit(e, out, err);
    return result;
  } catch (const CLI::ParseError& e) {
    // CLI11 2.1 says only "A subcommand is required" for an unknown first word: name it.
    std::string what = e.what();
    if (argc > 1 && argv[1][0] != '-' && app.get_subcommands().empty()) {
      std::string known;
      for (const auto* sub : app.get_subcommands({})) known += (known.empty() ? "" : ", ") + sub->get_name();
      what = "unknown command '" + std::string(argv[1]) + "'; commands: " + known;
    }
    err << "rangesim: " << what << "\nRun 'rangesim --help' or 'rangesim <command> --help'.\n";
    result.finished = true;
    result.exit_code = kExitBadInput;
    return result;
  }

  if (*list)
    c.kind = CommandKind::List;
  else if (*show)
    c.kind = CommandKind::Show;
  else if (*ev)
    c.kind = CommandKind::Evaluate;
  else if (*fr)
    c.kind = CommandKind::FrameRate;
  else if (*tb)
    c.kind = CommandKind::Table;
  else if (*sim)
    c.kind = CommandKind::Simulate;
  else if (*bench)
    c.kind = CommandKind::Bench;
  else if (*co)
    c.kind = CommandKind::Cosim;
  else if (*sw)
    c.kind = CommandKind::Sweep;
  else if (*mg)
    c.kind = CommandKind::Merge;
  else if (*cmp)
    c.kind = CommandKind::Compare;
  return result;
}

}  // namespace rangesim::app
