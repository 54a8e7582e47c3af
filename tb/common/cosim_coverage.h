#pragma once
// RTL coverage of the verilated models constructed in this process (those verilated with
// --coverage: the small co-simulation instances, see rtl/CMakeLists.txt). Verilator's counters
// are written to a coverage data file and the percentages computed here from its points:
//   line   = points of the pages v_line and v_branch (statement blocks and if/case branches)
//   toggle = points of the page v_toggle (each bit of each signal, both directions)
// hit = count > 0. The same numbers `verilator_coverage --annotate` would base itself on.
#include <string>

namespace rangesim::tb {

struct RtlCoverage {
  bool available = false;  // some model in this process carries coverage points
  long long line_points = 0, line_hit = 0;
  long long toggle_points = 0, toggle_hit = 0;
  double line_percent() const { return line_points ? 100.0 * line_hit / line_points : 0.0; }
  double toggle_percent() const { return toggle_points ? 100.0 * toggle_hit / toggle_points : 0.0; }
};

// Parses a Verilator coverage data file (coverage.dat format). Throws std::runtime_error if it
// cannot be read.
RtlCoverage parse_coverage_file(const std::string& path);

// Writes this process's counters to `path` ("" = a temporary file, removed again) and parses them.
RtlCoverage rtl_coverage(const std::string& path = "");

}  // namespace rangesim::tb
