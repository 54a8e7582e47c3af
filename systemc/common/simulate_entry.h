#pragma once
// A sensor's clock-level scene run as the `rangesim simulate` registry lists it
// (app/cmd_simulate.h): the run itself (systemc/<sensor>/simulate.cpp) and the knobs only some
// sensors have, which the command line checks before it runs anything. Declarations only, so the
// command-line parser can include it without SystemC or JSON.
#include <string>
#include <vector>

namespace rangesim {
class ParamSet;
}

namespace rangesim::systemc {

// A pixel of --trace-pixels: its row and column in the pixel array.
struct TracePixel {
  int row = 0, column = 0;
  bool operator==(const TracePixel& o) const { return row == o.row && column == o.column; }
};

struct SimulationRequest;
class SimulationHost;
struct SimulationResult;

// `params` is the validated preset with the command-line overrides applied.
using SceneRun = SimulationResult (*)(const SimulationRequest& request, const ParamSet& params, SimulationHost& host);

struct SimulateEntry {
  std::string sensor;  // preset id
  SceneRun run;        // the sensor's scene run
  bool aggregation;    // has an aggregated path that --no-aggregate switches off
  bool time_step;      // has a continuous-time integration that --time-step coarsens
  bool trace_rows;     // its waveform shows per-row blocks, chosen with --trace-rows
  bool trace_pixels;   // its waveform shows chosen pixels (--trace-pixels)
  bool threads;        // its bare kernel runs on several threads (--threads with --kernel-only)
};

}  // namespace rangesim::systemc
