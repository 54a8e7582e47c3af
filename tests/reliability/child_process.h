#pragma once
// Runs the built rangesim as a child process the way the reliability tests need it: in its own
// working folder, with an address-space limit, killed at a wall-time limit, and measured (exit
// code or signal, peak resident size, wall time); or started in the background to be signalled.
#include <string>
#include <sys/types.h>
#include <vector>

struct ChildResult {
  int exit_code = -1;      // -1 when ended by a signal
  int signal = 0;          // the signal that ended it (0: it exited)
  bool timed_out = false;  // killed at the wall-time limit
  long max_rss_kib = 0;    // peak resident size
  double wall_s = 0;
  std::string out, err;
};

struct ChildLimits {
  double wall_s = 60;                    // killed (SIGKILL) after this
  unsigned long long address_space = 0;  // RLIMIT_AS in bytes, 0: none
};

// Splits `args` like a shell would for the corpus: words separated by spaces, '...' quoting.
std::vector<std::string> split_args(const std::string& args);

// Runs `argv` (argv[0] is the program) in `cwd` and waits for it.
ChildResult run_child(const std::vector<std::string>& argv, const std::string& cwd, const ChildLimits& limits);

// Starts `argv` in `cwd` in the background with stdout/stderr to files in `cwd`; wait_child()
// collects it.
struct Background {
  pid_t pid = -1;
  std::string out_path, err_path;
};
Background start_child(const std::vector<std::string>& argv, const std::string& cwd);
ChildResult wait_child(const Background& b, double wall_s = 120);
