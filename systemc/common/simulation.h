#pragma once
// What a sensor's clock-level scene run (systemc/<sensor>/simulate.cpp) takes and gives back.
// The run returns data, never files: the range map, the per-point and per-frame CSV text, the
// summary as JSON and the figures the terminal summary prints; app/simulate/ renders every
// sensor's result the same way (files, plot, trace, text or --json).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "golden/common/frame_timing.h"
#include "systemc/common/simulate_entry.h"
#include "systemc/common/table.h"

namespace rangesim::systemc {

// The flags of `rangesim simulate` that shape the run (the command line parses them).
struct SimulationRequest {
  std::string scene;                // --scene FILE.toml ("" = missing; the sensor names an example)
  std::optional<long long> frames;  // --frames N (default: the sensor's, e.g. one range map)
  std::uint64_t seed = 1;           // --seed S: key of the noise streams
  bool kernel_only = false;         // --kernel-only: bare C++ kernels, no SystemC elaboration
  bool tick = false;                // --tick: every clock cycle evaluated (kernel only)
  bool noise_free = false;          // --noise-free: all noise sources off
  bool dense = false;               // --dense: every pixel (no sparse window)
  bool no_aggregate = false;        // --no-aggregate: periods / laser cycles one by one
  double time_step_s = 0;           // --time-step S (0 = exact closed form)
  int threads = 1;                  // --threads N with --kernel-only (default: all cores), where the sensor can
  std::vector<int> trace_rows;      // --trace-rows: rows whose blocks the waveform shows (empty: the sensor's choice)
  std::vector<TracePixel> trace_pixels;  // --trace-pixels: pixels the waveform shows (empty: the sensor's choice)
  // --points: the per-point table's rows. Without it a run may return the table's columns only
  // (a full ls-conventional map's rows are 9.6 MB of .npy); the Python module always asks.
  bool points = true;
};

// A traced pixel's checks: inside the simulated window [first, first + count) in both axes, or a
// UserError naming the flag, the pixel and the window ("what" describes the window).
void check_trace_pixels(const std::vector<TracePixel>& pixels, int first_row, int rows, int first_column, int columns,
                        const std::string& what);

// What the run asks of the command around it, at the points where the sensor's checks allow:
// the trace and the output folder are claimed before the model runs, so a bad --trace or --out
// fails before the work and in the same order as the sensor's own checks.
struct RangeMap;

// Work the host began on a finished range map while the run went on (SimulationHost::map_ready):
// it ends, waiting for that work, when this object goes.
class MapWork {
 public:
  virtual ~MapWork() = default;
};

class SimulationHost {
 public:
  virtual ~SimulationHost() = default;
  // Checks --trace; returns the base name of the VCD the SystemC model writes ("" = no trace).
  virtual std::string open_trace() = 0;
  // Claims the output folder (--out, or one named after the scene).
  virtual void open_output(const std::string& scene_name) = 0;
  // Progress of a long run: called with the count of `unit`s done (of `total`).
  virtual std::function<void(long long done)> progress(const std::string& unit, long long total) = 0;
  // The run's estimate of its peak memory, made before the model runs: a run that cannot fit is
  // refused here (UserError naming `what` and the flags in `reduce`) instead of being ended late.
  virtual void check_memory(double bytes, const std::string& what, const std::string& reduce) = 0;
  // The map's range_m, confidence, column_names, labels and title are final while the run goes on
  // (its truth, the counts): the host may begin writing them on another thread. It reads them
  // through their rows' storage, which stays in place when the map is moved; the run keeps the
  // returned object (null: nothing begun) until it hands the map back, declared after the map so
  // that it ends first (SimulationResult::map_work).
  virtual std::unique_ptr<MapWork> map_ready(const RangeMap& /*map*/) { return nullptr; }
  // Then its truth_m too (after map_ready, while that object lives): the same for what needs it.
  virtual void truth_ready(const RangeMap& /*map*/) {}
};

// Range error of detected points against the ground truth (m; px where the sensor has one).
struct RangeErrorStats {
  long long detected = 0;  // points with a range and a truth
  double sum_sq_m = 0, sum_m = 0, max_abs_m = 0;
  double sum_sq_px = 0;  // image-position error, light-section sensors
  void add(double error_m, double error_px = 0) {
    ++detected, sum_sq_m += error_m * error_m, sum_m += error_m, sum_sq_px += error_px * error_px;
    max_abs_m =
        error_m < 0 ? (-error_m > max_abs_m ? -error_m : max_abs_m) : (error_m > max_abs_m ? error_m : max_abs_m);
  }
  double rms_m() const;
  double rms_px() const;
  double mean_m() const;
  // range_error_rms_m, range_error_mean_m, range_error_max_abs_m (+ range_error_rms_px if with_px)
  void to_json(nlohmann::json& j, bool with_px) const;
};

// The terminal summary's figures (the same layout for every sensor): measured vs golden timing,
// the points and the range error, and the sensor's own lines.
struct SimulationReport {
  std::string headline;     // first line, e.g. "tof-spad on scene 'x' (plane): 3 frames, SystemC, noise seed 1"
  nlohmann::json phases;    // array of {name, cycles, golden_cycles, time_s}
  std::string frame_label;  // "frame" or "frame access"
  long long frame_cycles = 0, golden_frame_cycles = 0;
  double frame_time_s = 0, golden_frame_time_s = 0;
  double frame_rate_Hz = 0, golden_frame_rate_Hz = 0;
  bool timing_matches = true;
  double range_maps_per_s = 0;
  long long frames_per_range_map = 1;
  std::string points_line;  // e.g. "points visible 10, detected 9, missed 1, false 0"
  RangeErrorStats error;
  bool error_in_px = false;  // print the rms in px too
  std::string error_note;    // appended to the range-error line, e.g. "(golden accuracy 3 mm)"
  double wall_time_s = 0;
  std::string wall_note;  // appended to the wall-time line
};

// The measured timing beside the golden clock schedule, the same for every sensor: `phases` as
// in the report, the first frame's cycles, the mean frame time over the run (simulated time /
// frames) and whether every frame took the golden cycle counts.
void set_timing(SimulationReport& r, const golden::FrameTiming& gt, nlohmann::json phases, long long first_frame_cycles,
                double frame_time_s, long long frames_per_range_map, bool matches);
// A frame's phases as the clock-level model measured them beside the clock schedule's: name,
// cycles, time at `clock_Hz`, golden_cycles (`measured` in the schedule's phase order).
template <class Cycles>
nlohmann::json phases_json(const golden::FrameTiming& gt, const Cycles& measured, double clock_Hz) {
  nlohmann::json phases = nlohmann::json::array();
  for (std::size_t i = 0; i < gt.phases.size(); ++i)
    phases.push_back({{"name", gt.phases[i].name},
                      {"cycles", measured[i]},
                      {"time_s", measured[i] / clock_Hz},
                      {"golden_cycles", gt.phases[i].cycles}});
  return phases;
}
// The summary's timing keys from a report set_timing filled: frame_time_s, frame_rate_Hz,
// range_maps_per_s, phases, timing_matches_golden and golden {frame_cycles, frame_time_s,
// frame_access_rate_Hz, range_maps_per_s} (a sensor may add its own golden keys).
void add_timing_json(nlohmann::json& j, const SimulationReport& r, const golden::FrameTiming& gt);

// The range map: rows of ranges in m, NaN where a pixel (or beam position) has no valid range.
struct RangeMap {
  std::vector<std::vector<double>> range_m;
  // A pixel's validity is carried by its value: a finite range is a pixel the sensor's validity
  // rule accepted; the others are no ranges (CSV and plot leave them empty, the error metrics skip
  // them).
  bool valid(std::size_t row, std::size_t column) const { return std::isfinite(range_m[row][column]); }
  // The ground truth each range is scored against (same shape), NaN where the scene puts no echo
  // on the pixel (not visible, outside the beam): range_m - truth_m is the error map the Python
  // module returns. Not written by the command (points.csv has the errors point by point).
  std::vector<std::vector<double>> truth_m;
  // What the validity rule tested, per pixel (same shape; NaN where nothing was measured), in the
  // unit of `confidence_label`; written as confidence_map.csv.
  std::vector<std::vector<double>> confidence;
  std::string confidence_label;                 // e.g. "peak significance [sigma]"
  std::string validity_rule;                    // the rule, with its preset key and value
  std::vector<std::string> column_names;        // range_map.csv's columns after "row"
  int first_row = 0;                            // range_map.csv's label of range_m[0]
  std::string title, x_label, y_label = "row";  // range_map.png
};

// The range map's validity against the scene's ground truth (a pixel has an echo where truth_m
// is finite): summary.json's valid_fraction (valid pixels over all), false_valid_fraction (valid
// pixels where the scene puts no echo, over those pixels; null when every pixel has one) and
// echo_valid_fraction (valid pixels among those with an echo), and "validity" with the counts
// and the rule.
struct ValidityStats {
  long long pixels = 0, valid = 0;
  long long no_echo = 0, false_valid = 0;
  long long echo = 0, echo_valid = 0;
};
ValidityStats validity_of(const RangeMap& map);
void add_validity_json(nlohmann::json& j, const RangeMap& map);

struct SimulationResult {
  RangeMap range_map;
  Table points;             // points.csv / points.npy (empty: the sensor has none; written with --points)
  std::string frames_csv;   // frames.csv
  nlohmann::json summary;   // summary.json (the renderer adds warnings and the trace)
  SimulationReport report;  // the terminal summary
  std::unique_ptr<MapWork> map_work;  // what the host began on range_map (declared after it)
};

// Number for CSV (printf "%.9g", "" for NaN/inf) and for JSON (null for NaN/inf).
std::string csv_number(double v);
nlohmann::json json_number(double v);
// range_map.csv: "row,<column names>", then one line per row (values in m, empty where no range).
std::string range_map_csv(const RangeMap& map);
// confidence_map.csv: the same layout with the confidence values (empty where none).
std::string confidence_map_csv(const RangeMap& map);

}  // namespace rangesim::systemc
