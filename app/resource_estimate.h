#pragma once
// What a run will need, estimated before it starts: memory (checked against --max-memory, or
// without it against the memory available now) and disk (against the free space where the
// outputs go). A run that cannot fit is refused up front (UserError, exit 2) with the estimate,
// what it is made of and the flags that reduce it, instead of failing or being killed late.
#include <cstdint>
#include <string>

namespace rangesim::app {

struct ResourceEstimate {
  double memory_bytes = 0;  // peak resident size
  double disk_bytes = 0;    // size of the outputs
  std::string what;         // what the estimate counts, e.g. "100000000 grid points at ~1 KiB"
  std::string reduce;       // the flags that reduce it, e.g. "--signal/--background N"
};

// Resident size of the process before the work: the libraries, the registries, the preset.
inline constexpr double kBaseMemoryBytes = 32.0 * (1 << 20);

// Throws UserError naming `command`, the estimate and `reduce` when the run cannot fit; `dir` is
// where the outputs go ("" for none). RANGESIM_SKIP_ESTIMATES=1 in the environment skips the check
// (tests/reliability uses it to reach the run-time watchdog).
void check_resources(const std::string& command, const ResourceEstimate& e, const std::string& dir);

}  // namespace rangesim::app
