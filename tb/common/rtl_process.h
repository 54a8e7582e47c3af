#pragma once
// Running the tools of the run-time verilation (Verilator, the compiler) as child processes.
#include <sys/types.h>

#include <string>
#include <vector>

namespace rangesim::tb {

// Absolute path of `name` on PATH ("" if absent); a name with '/' is checked as it is.
std::string find_program(const std::string& name);

// In a child just forked from `parent`: dies with SIGTERM when the parent does, so a parent that
// is ended at once (a signal, a budget) leaves no build or model run behind.
void die_with_parent(pid_t parent);

// Runs argv in `cwd` ("" = here) with stdout and stderr to `log` ("" = this process's stderr);
// its exit status (128 + signal when killed).
int run_program(const std::vector<std::string>& args, const std::string& cwd, const std::string& log);

// The last `lines` lines of a log file, each indented by two spaces.
std::string log_tail(const std::string& path, int lines);

}  // namespace rangesim::tb
