#pragma once
// The rangesim subcommands. Each returns the process exit code (see cli_common.h) and throws
// UserError for bad input, NotModelled for a sensor without a model for the command.
#include <optional>
#include <string>
#include <vector>

namespace rangesim::app {

struct ListOptions {
  bool json = false;
};
int run_list(const ListOptions& opt);

struct ShowOptions {
  std::string preset;  // id or path
  bool json = false;
  std::vector<std::string> settings = {};  // --set KEY=VALUE, in order
};
int run_show(const ShowOptions& opt);

struct EvaluateOptions {
  std::string sensor;                 // preset id or path
  std::vector<std::string> settings;  // --set KEY=VALUE, in order, after the preset
  std::optional<std::string> signal;  // "LO:HI:N" volts
  std::optional<std::string> background;
  // Physical axes (app/physical_axes.h): lux of ambient light at the target and watts of source
  // power, converted by the sensor's radiometry under `scene` ("" = the default scene).
  std::optional<std::string> background_lux;
  std::optional<std::string> signal_power;
  std::string scene;
  // Integer flags are held wide: the sensor's own range is checked when they are applied, so
  // --frames 1e12 is refused naming that range instead of failing to convert.
  std::optional<long long> samplings;
  std::optional<long long> adc_bits;
  std::optional<long long> frames;  // frames averaged
  std::string out;                  // output directory ("" -> rangesim-out/<sensor>)
  bool force = false;               // --force: replace the results of another kind of run in --out
  bool json = false;
  bool no_plots = false;
  // Monte Carlo on the clock-level kernels (app/montecarlo/, docs/evaluate-montecarlo.md); any of
  // trials / target_error switches it on.
  std::optional<long long> trials;         // trials per grid point (first batch)
  std::optional<double> target_error;      // m: add trials until the accuracy's 95% CI half-width <= this
  std::optional<long long> max_trials;     // cap per point (trial budget)
  std::optional<int> threads;              // worker threads (default: all cores)
  std::optional<unsigned long long> seed;  // key of the random streams
  std::optional<double> max_seconds;       // wall-time budget of the command (Monte Carlo: of the sweep)
  bool resume = false;                     // continue the sweep journal in --out
};
int run_evaluate(const EvaluateOptions& opt);
// `evaluate` with --trials / --target-error (app/montecarlo/cmd_evaluate_mc.cpp).
int run_evaluate_mc(const EvaluateOptions& opt);

// rangesim compare (app/compare/compare.h): CompareOptions and run_compare live there.

struct FrameRateOptions {
  std::string sensor;
  std::optional<long long> samplings;
  bool json = false;
  std::vector<std::string> settings = {};  // --set KEY=VALUE, in order
};
int run_frame_rate(const FrameRateOptions& opt);

struct TableOptions {
  bool json = false;
  bool published = false;  // also list the chips' published figures on the terminal
  std::string out;         // "" -> nothing written
  bool force = false;      // --force: replace the results of another kind of run in --out
};
int run_table(const TableOptions& opt);

// rangesim sweep (app/sweep/): architecture variants of one preset.
struct SweepOptions {
  std::string sensor;                 // preset id or path
  std::vector<std::string> settings;  // --set KEY=VALUE before the variants
  std::vector<std::string> vary;      // --vary KEY=LO:HI:N[:log] | KEY=v1,v2,...
  bool zip = false;                   // --zip: the i-th values together, not the cross product
  std::optional<std::string> shard;   // --shard K/N: every N-th variant from the K-th
  std::string out;                    // --out DIR ("" -> rangesim-out/sweep/<sensor>)
  bool force = false;                 // --force: replace the results of another kind of run in --out
  bool json = false;
  bool no_plots = false;
  bool resume = false;                      // continue the journal in --out
  std::string pareto_accuracy = "min";      // --pareto-accuracy min|max: best or worst accuracy on the front's axis
  std::optional<long long> trials;          // --trials T: Monte Carlo accuracy with its CI per variant
  unsigned long long seed = 1;              // --seed: key of the Monte Carlo and cosim streams
  bool cosim = false;                       // --cosim: each variant's RTL against its model
  unsigned long long cosim_cycles = 20000;  // --cosim-cycles
};
int run_sweep(const SweepOptions& opt);
// rangesim merge: the shards of one sweep into its unsharded output.
struct MergeOptions {
  std::vector<std::string> parts;  // sweep.shard-K-of-N.json files
  std::string out;
  bool force = false;  // --force: replace the results of another kind of run in --out
  bool json = false;
  bool no_plots = false;
  std::string pareto_accuracy = "min";
};
int run_merge(const MergeOptions& opt);

// rangesim bench (app/cmd_bench.cpp, app/bench/, docs/bench.md).
struct BenchOptions {
  bool quick = false;   // --quick: the same keys in under two minutes (fewer frames for the references)
  bool json = false;    // --json: bench.json to stdout instead of the tables
  std::string out;      // --out DIR ("" -> rangesim-out/bench)
  bool force = false;   // --force: replace the results of another kind of run in --out
  bool resume = false;  // --resume: continue a killed or interrupted bench from its journal in DIR
};
// 0 when every identity check inside the bench passed (speed targets are reported, not
// enforced), 1 when one failed; throws UserError for an unusable --out.
int run_bench(const BenchOptions& opt);
// `rangesim cosim` (app/cmd_cosim.cpp): RTL co-simulation targets of tb/common/cosim_targets.cpp.
inline constexpr int kExitCosimMismatch = 4;  // the run completed and found mismatches
struct CosimCommandOptions {
  std::string target;                        // sensor id, block name, "all" or a preset file ("" with --list)
  std::vector<std::string> settings;         // --set KEY=VALUE after a preset (not for built-in targets)
  std::optional<unsigned long long> cycles;  // clock cycles (default 100000)
  unsigned long long seed = 1;
  std::string trace;             // RTL VCD file ("" = none)
  std::string junit;             // JUnit XML file ("" = none)
  std::string coverage_out;      // Verilator coverage.dat file ("" = none)
  std::vector<std::string> rtl;  // --rtl: the user's Verilog files
  std::string top;               // --top: the block they implement ("" = every block they define)
  std::string inject_fault;      // a fault name of the target ("" = none)
  bool json = false;
  bool list = false;
  // `all` journals each finished target (app/sweep_journal.h) so that a killed or interrupted run
  // continues with --resume; the journal is removed when the run completes.
  std::string journal = "rangesim-out/cosim/all.journal";
  bool resume = false;
};
int run_cosim(const CosimCommandOptions& opt);
// Whether `cosim <sensor>` has a target (false in a build without Verilator).
bool cosim_runs(const std::string& sensor);

}  // namespace rangesim::app
