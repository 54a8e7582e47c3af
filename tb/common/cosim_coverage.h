#pragma once
// RTL coverage of the verilated models constructed in this process (those verilated with
// --coverage: the small co-simulation instances, see rtl/<sensor>/instances.cmake). Verilator's counters
// are written to a coverage data file and the percentages computed here from its points:
//   line   = points of the pages v_line and v_branch (statement blocks and if/case branches)
//   toggle = points of the page v_toggle (each bit of each signal, both directions)
// hit = count > 0. The same numbers `verilator_coverage --annotate` would base itself on.
#include <map>
#include <set>
#include <string>

namespace rangesim::tb {

struct RtlCoverage {
  bool available = false;  // some model in this process carries coverage points
  long long line_points = 0, line_hit = 0;
  long long toggle_points = 0, toggle_hit = 0;
  // Source lines with a line or branch point never hit, by file (rangesim's own RTL as
  // "rtl/<folder>/<file>.sv", a user's file by the path it was given).
  std::map<std::string, std::set<int>> uncovered_lines;
  std::string data;  // the counters in Verilator's coverage.dat format (verilator_coverage reads it)
  double line_percent() const { return line_points ? 100.0 * line_hit / line_points : 0.0; }
  double toggle_percent() const { return toggle_points ? 100.0 * toggle_hit / toggle_points : 0.0; }
};

// Parses Verilator coverage data (coverage.dat format).
RtlCoverage parse_coverage_data(const std::string& data);

// Reads the counters of the models alive now and keeps them for rtl_coverage(). The counters live
// in the models: read after a model is destroyed they are freed memory, and the numbers change
// with anything that moves the heap. Every co-simulation runner calls it before its top goes
// (tb/common/cosim_run.h).
void capture_rtl_coverage();

// The counters captured last (or, if none were, those of the models alive now).
RtlCoverage rtl_coverage();

}  // namespace rangesim::tb
