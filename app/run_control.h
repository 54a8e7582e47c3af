#pragma once
// How a run of rangesim ends when it is asked to stop before it is done: by a signal (SIGINT,
// SIGTERM, SIGHUP) or by a budget running out (--max-seconds, --max-memory).
//
// A sweep that journals its points (evaluate --trials, sweep, bench, cosim all) stops between
// points: while a StopGuard lives, a stop only raises stop_flag(); the sweep keeps its journal,
// prints stop_reason() and the command that resumes, and returns stop_exit_code().
//
// Any other run is ended at once: the temporary paths it registered (staging folders, partial
// traces, the output folder's lock) are removed, one line on stderr says why, and the process
// exits with 128 + the signal (130 Ctrl-C, 143 SIGTERM, 129 SIGHUP) or kExitBudget. A stop that
// arrives while an output folder is being committed waits for the commit (CommitSection), so a
// folder is never left half-replaced.
#include <atomic>
#include <cstdint>
#include <string>

namespace rangesim::app {

inline constexpr int kExitBudget = 4;  // --max-seconds or --max-memory ran out

// Installs the handlers of SIGINT, SIGTERM and SIGHUP (main(), once); a signal ignored by the
// caller (nohup) stays ignored.
void install_stop_handlers();

// Paths removed when a run is ended at once; `tree` removes a folder with its contents, otherwise
// a file or an empty folder is removed. Returns a slot for unregister_cleanup (-1: table full).
int register_cleanup(const std::string& path, bool tree);
// The same for every entry of folder D whose name starts with P (files and folders with their
// contents), given as "D/P": a run's staged files (app/output_dir.h).
int register_prefix_cleanup(const std::string& folder_and_prefix);
void unregister_cleanup(int slot);

// While one lives, a stop waits until it ends (then ends the run, whose outputs are complete).
class CommitSection {
 public:
  CommitSection();
  ~CommitSection();
  CommitSection(const CommitSection&) = delete;
  CommitSection& operator=(const CommitSection&) = delete;
};

// While one lives, a stop raises stop_flag() instead of ending the run. Cleared on construction.
class StopGuard {
 public:
  StopGuard();
  ~StopGuard();
  StopGuard(const StopGuard&) = delete;
  StopGuard& operator=(const StopGuard&) = delete;
};
std::atomic<bool>& stop_flag();
int stop_exit_code();       // 128 + signal, or kExitBudget
std::string stop_reason();  // "interrupted (SIGINT, Ctrl-C)", "--max-memory 1G exceeded (...)", ...

// The budgets of this run, counted from the start of the process. The memory budget is watched
// for every run (resident size, every 0.1 s; without --max-memory, 90% of the memory available at
// the start, so a run that would be killed for memory ends with a message instead); the time
// budget only ends runs outside a StopGuard: a guarded sweep checks time_budget_left() between its
// points itself.
struct RunBudget {
  double max_seconds = 0;                         // 0: none
  std::uint64_t max_memory_bytes = 0;             // 0: none
  std::string max_seconds_text, max_memory_text;  // as given, for messages
};
void start_budget(const RunBudget& budget);
// Ends the run now as a budget that ran out does (cleanup, `message`, kExitBudget): for a run whose
// pace shows it cannot finish within --max-seconds.
[[noreturn]] void end_run_over_budget(const std::string& message);
const RunBudget& run_budget();
double seconds_since_start();
double time_budget_left();  // seconds; +inf without a time budget
std::uint64_t resident_bytes();
std::uint64_t available_memory_bytes();  // MemAvailable of /proc/meminfo (0 when unknown)
std::string bytes_text(double bytes);    // "1.5 GiB"

// The command line of this run (main()), for lock files and messages.
void set_command_line(int argc, const char* const* argv);
const std::string& command_line();
// `s` as one word for the shell (printed commands).
std::string shell_quote(const std::string& s);

}  // namespace rangesim::app
