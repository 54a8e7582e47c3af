#pragma once
// The parts every `rangesim simulate` implementation shares after its model has run: progress on
// long runs, the range-error statistics, the timing/phase table printed for people, and the
// common tail (summary.json, trace, commit, --json). Each sensor keeps only what is its own:
// scene, stimulus, run and ground truth.
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/output_dir.h"
#include "app/simulate/trace_output.h"

namespace rangesim::app {

struct SimulateOptions;

// Progress on stderr for runs longer than a couple of seconds: at most once a second, from 2 s
// after `start` on, and at the end. `unit` names what is counted ("frame", "frame access").
class Progress {
 public:
  using Clock = std::chrono::steady_clock;
  Progress(std::string unit, long long total, Clock::time_point start, std::FILE* to = stderr);
  void operator()(long long done);
  int reports() const { return reports_; }  // lines printed so far

 private:
  std::string unit_;            // what is counted
  long long total_;             // count at the end
  Clock::time_point start_;     // start of the command
  Clock::time_point last_;      // last line printed
  std::FILE* to_;               // stream
  int reports_ = 0;             // lines printed
};

// Range error of detected points against the ground truth (m; px where the sensor has one).
struct RangeErrorStats {
  long long detected = 0;         // points with a range and a truth
  double sum_sq_m = 0, sum_m = 0, max_abs_m = 0;
  double sum_sq_px = 0;           // image-position error, light-section sensors
  void add(double error_m, double error_px = 0) {
    ++detected, sum_sq_m += error_m * error_m, sum_m += error_m, sum_sq_px += error_px * error_px;
    max_abs_m = error_m < 0 ? (-error_m > max_abs_m ? -error_m : max_abs_m) : (error_m > max_abs_m ? error_m : max_abs_m);
  }
  double rms_m() const;
  double rms_px() const;
  double mean_m() const;
  // range_error_rms_m, range_error_mean_m, range_error_max_abs_m (+ range_error_rms_px if with_px)
  void to_json(nlohmann::json& j, bool with_px) const;
};

// What the people-facing summary prints (the same layout for every sensor; times in a unit that
// fits the frame: ns, us or ms).
struct SimulateSummary {
  std::string headline;            // first line, e.g. "tof-spad on scene 'x' (plane): 3 frames, SystemC, noise seed 1"
  nlohmann::json phases;           // array of {name, cycles, golden_cycles, time_s}
  std::string frame_label;         // "frame" or "frame access"
  long long frame_cycles = 0, golden_frame_cycles = 0;
  double frame_time_s = 0, golden_frame_time_s = 0;
  double frame_rate_Hz = 0, golden_frame_rate_Hz = 0;
  bool timing_matches = true;
  double range_maps_per_s = 0;
  long long frames_per_range_map = 1;
  std::string points_line;         // e.g. "points visible 10, detected 9, missed 1, false 0"
  RangeErrorStats error;
  bool error_in_px = false;        // print the rms in px too
  std::string error_note;          // appended to the range-error line, e.g. "(golden accuracy 3 mm)"
  double wall_time_s = 0;
  std::string wall_note;           // appended to the wall-time line
};
void print_summary(const SimulateSummary& s, std::FILE* to = stdout);

// The common tail: writes summary.json (with any warnings), finishes the trace, commits the
// output folder and the trace, then prints either the JSON (--json) or `summary` and the files
// written. Nothing is left half-written if any step throws.
int finish_simulate(const SimulateOptions& opt, OutputDir& out, TraceOutput& trace, nlohmann::json& j,
                    const std::string& plot_warning, const SimulateSummary& summary);

}  // namespace rangesim::app
