#pragma once
// Helpers of `rangesim bench` (docs/bench.md): wall-clock timing, running a measurement in a
// forked child (SystemC allows one elaboration per process, and the bench needs several), running
// the rangesim binary itself as a timed child (the Pareto rows, output_share), and progress lines on stderr.
#include <chrono>
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace rangesim::app::bench {

using Clock = std::chrono::steady_clock;
inline double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }
// CPU time of this process (user + system), s. The figures are ratios of CPU times: on a shared
// machine the wall time depends on the other users' load, the CPU time of a single-threaded run
// does not.
double cpu_now();
// CPU time of the waited-for child processes (getrusage RUSAGE_CHILDREN), s.
double children_cpu_now();

// Runs `job` in a forked child and returns the JSON it produced. The child's exceptions come back
// as {"error": "..."}; a crash as {"error": "child ended with status N"}. Needed for every
// SystemC elaboration: each gets a fresh process.
nlohmann::json run_in_child(const std::function<nlohmann::json()>& job);

// One run of this rangesim binary with `args`, started directly (no shell) and timed as one whole
// process, start-up included: its wall time from fork to exit, its CPU time (wait4), its stdout
// (stderr is discarded) and its exit code.
struct SelfRun {
  int exit_code = 0;
  std::string out;
  double wall_s = 0, cpu_s = 0;
};
SelfRun run_self_timed(const std::vector<std::string>& args);

// "bench: <what>" on stderr with the elapsed time since the bench started.
void progress(const std::string& what);
void set_progress_start(Clock::time_point t0);

// Directory of the example scenes (scenes/ in the source tree, or <prefix>/share/rangesim/scenes).
std::string scene_path(const std::string& file);

}  // namespace rangesim::app::bench
