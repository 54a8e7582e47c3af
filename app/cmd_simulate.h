#pragma once
// rangesim simulate: the clock-level model of a sensor run on a scene (docs/simulate.md).
// Kept apart from app/commands.h so the command can be wired in with two lines (see the report
// in docs/simulate.md, "Wiring").
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace rangesim::app {

struct SimulateOptions {
  std::string sensor;               // preset id or path (only ls-conventional has a clock-level model)
  std::string scene;                // --scene FILE.toml (required)
  std::optional<long long> frames;  // --frames N: frame accesses (default: one range map = beam_positions)
  std::uint64_t seed = 1;           // --seed S: key of the noise streams
  std::string trace;                // --trace FILE.vcd or FILE.fst ("" = no waveform); SystemC only
  std::string out;                  // --out DIR ("" -> rangesim-out/simulate/<scene name>)
  bool json = false;                // --json: summary.json to stdout instead of the table
  bool kernel_only = false;         // --kernel-only: bare C++ kernels, no SystemC elaboration
  bool tick = false;                // --tick / --no-event-skip: evaluate every clock cycle (no event skipping; kernel only)
  bool noise_free = false;          // --noise-free: all noise sources off
  bool dense = false;               // --dense / --no-sparse: simulate every pixel (no sparse window)
  bool no_aggregate = false;        // --no-aggregate: ls-demodulation correlation periods / tof-lockin accumulation periods / tof-spad laser cycles one by one
  bool no_plots = false;            // --no-plots: skip range_map.png
  double time_step_s = 0;           // --time-step S: tof-lockin pulse/gate overlaps integrated at step S (0 = exact closed form)
};

// Returns the exit code; throws UserError (exit 2) for bad input, NotModelled (exit 3) for a
// sensor without a clock-level model.
int run_simulate(const SimulateOptions& opt);

}  // namespace rangesim::app

namespace rangesim {
class ParamSet;
}

namespace rangesim::app {

// A sensor's clock-level simulation (app/simulate/simulate_<sensor>.cpp): `params` is the
// validated preset with the command-line overrides applied.
struct SimulateEntry {
  std::string sensor;  // preset id
  int (*run)(const SimulateOptions& opt, const ParamSet& params);
  bool aggregation;  // has an aggregated path that --no-aggregate switches off
  bool time_step;    // has a continuous-time integration that --time-step coarsens
};
// The shipped sensors' simulations (core/sensor_list.h), then any added at run time.
std::vector<SimulateEntry>& simulate_registry();

}  // namespace rangesim::app
