#pragma once
// The jobs of simulate's output (app/simulate/simulate_render.cpp) run side by side.
#include <functional>
#include <memory>
#include <vector>

namespace rangesim::app {

// Runs every job once on up to `threads` threads (the caller's among them), taking them in order
// as threads come free; when all have ended, rethrows the failure of the first job that failed.
// Each helper thread starts on a CPU of the process's set other than the caller's, then may run on
// any of them: on a virtual machine whose scheduler packs threads onto few CPUs, a helper started
// beside the caller waited for it (in 10 to 20 of 20 tries, tests/simulate/test_run_jobs.cpp), and
// a full map's outputs took 3.3 to 3.5 ms of wall against 2.6 to 2.7 ms started elsewhere
// (medians of 41 runs from a shell loop, two alternations, measured).
void run_jobs(const std::vector<std::function<void()>>& jobs, int threads);

// Jobs run in order on one helper thread, started on another CPU as run_jobs's helpers are, while
// the caller goes on and may add more. wait() takes no more: the caller runs what is still queued
// beside the helper (alone where no thread could be made), joins it and rethrows the first failure
// (the first to happen); the destructor does the same and drops the failure. Handing the last jobs
// to a helper that already runs saves starting a thread (0.3 to 0.5 ms of wall on this 2-CPU
// virtual machine for the two small files left after a map's).
class BackgroundJobs {
 public:
  explicit BackgroundJobs(std::vector<std::function<void()>> jobs);
  ~BackgroundJobs();
  BackgroundJobs(const BackgroundJobs&) = delete;
  BackgroundJobs& operator=(const BackgroundJobs&) = delete;
  void add(std::function<void()> job);
  void wait();
  // The helper's CPU time so far, s (all of it once it has ended).
  double cpu_s() const;

 private:
  struct State;
  std::unique_ptr<State> s_;
};

}  // namespace rangesim::app
