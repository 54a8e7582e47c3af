#pragma once
// The jobs of simulate's output (app/simulate/simulate_render.cpp) run side by side.
#include <functional>
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

}  // namespace rangesim::app
