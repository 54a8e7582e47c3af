#pragma once
// rangesim simulate: the clock-level model of a sensor run on a scene (docs/simulate.md).
// Kept apart from app/commands.h so the command can be wired in with two lines (see the report
// in docs/simulate.md, "Wiring").
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/params.h"
#include "systemc/common/simulate_entry.h"

namespace rangesim::app {

struct SimulateOptions {
  std::string sensor;                 // preset id or path
  std::vector<std::string> settings;  // --set KEY=VALUE after the preset
  std::string scene;                  // --scene FILE.toml (required)
  std::optional<long long> frames;    // --frames N: frame accesses (default: one range map = beam_positions)
  std::uint64_t seed = 1;             // --seed S: key of the noise streams
  std::string trace;                  // --trace FILE.vcd or FILE.fst ("" = no waveform); SystemC only
  std::vector<int> trace_rows;        // --trace-rows: rows the waveform shows (empty: the sensor's choice)
  std::vector<systemc::TracePixel> trace_pixels;  // --trace-pixels R:C,...: pixels the waveform shows (empty: the
                                                  // sensor's choice)
  std::string out;                                // --out DIR ("" -> rangesim-out/simulate/<scene name>)
  bool force = false;                             // --force: replace the results of another kind of run in --out
  bool json = false;                              // --json: summary.json to stdout instead of the table
  bool kernel_only = false;                       // --kernel-only: bare C++ kernels, no SystemC elaboration
  bool tick = false;          // --tick / --no-event-skip: evaluate every clock cycle (no event skipping; kernel only)
  bool noise_free = false;    // --noise-free: all noise sources off
  bool dense = false;         // --dense / --no-sparse: simulate every pixel (no sparse window)
  bool no_aggregate = false;  // --no-aggregate: ls-demodulation correlation periods / tof-lockin accumulation periods /
                              // tof-spad laser cycles one by one
  bool no_plots = false;      // --no-plots: skip range_map.png and range_error.png
  bool points = false;        // --points: write the per-point table (points.csv / points.npy)
  // --csv / --npy: range map and points as CSV / as .npy; default: .npy for a table of more than
  // kNpyMinValues numbers, CSV for smaller ones (simulate_render.h). frames.csv is always CSV.
  bool csv = false;
  bool npy = false;
  double time_step_s = 0;  // --time-step S: tof-lockin pulse/gate overlaps integrated at step S (0 = exact closed form)
  std::optional<int> threads;  // --threads N: the bare kernel's threads (default: all cores where the sensor can)
};

// Returns the exit code; throws UserError (exit 2) for bad input, NotModelled (exit 3) for a
// sensor without a clock-level model.
int run_simulate(const SimulateOptions& opt);

// A sensor's clock-level scene run and its knobs (systemc/common/simulate_entry.h), defined in
// systemc/<sensor>/simulate.cpp; app/simulate/simulate_render.cpp runs and renders it.
using SimulateEntry = systemc::SimulateEntry;
// The shipped sensors' scene runs (core/sensor_list.h), then any added at run time.
std::vector<SimulateEntry>& simulate_registry();
// Whether `simulate` runs for the sensor (it has a scene run).
bool simulate_runs(const std::string& sensor);

// The scene run of the preset's sensor, with the flags only some runs take checked against it:
// NotModelled without a clock-level model, UserError for --no-aggregate / --time-step where the
// run has no such path. (`opt.sensor` and the file flags are not read.)
const SimulateEntry& simulate_entry_for(const ParamSet& params, const SimulateOptions& opt);

// SystemC's informational reports off, its warnings and errors to stderr (stdout may carry JSON).
void route_systemc_reports_to_stderr();

}  // namespace rangesim::app
