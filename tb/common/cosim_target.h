#pragma once
// One co-simulation target per RTL block or sensor, run by `rangesim cosim <target>` and by the
// ctest cosim suites. Each target drives its verilated RTL beside its SystemC model (and the
// golden model where it is exact) on randomised stimulus drawn from the seed, and reports what
// its scoreboard compared. Targets live in tb/<block>_cosim.cpp and are listed in
// tb/common/cosim_targets.cpp (one line each).
#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace rangesim::tb {

struct CosimOptions {
  std::uint64_t cycles = 100000;  // clock cycles to simulate (the target rounds up to whole transactions)
  std::uint64_t seed = 1;         // stimulus, parameters within their ranges, Verilator's initial state
  std::string inject_fault;       // empty: none; else one of CosimTarget::faults
  std::string trace_path;         // empty: no waveforms; else a VCD of the RTL run
};

// One mismatch, readable at a glance: where (frame, row, column, cycle), what, expected, actual.
struct CosimMismatch {
  std::string check;  // scoreboard check id, e.g. "address", "centre", "gate_edge", "tdc_code"
  long long frame = -1, row = -1, column = -1;  // -1: not applicable
  std::uint64_t cycle = 0;
  std::string expected, actual;
};

// CosimReport::first_mismatches keeps this many (every scoreboard goes through
// tb/common/cosim_scoreboard.h); the rest are counted.
inline constexpr std::size_t kKeptMismatches = 20;

// What one check of a scoreboard compared (a JUnit testcase of its own).
struct CosimCheck {
  std::uint64_t transactions = 0, mismatches = 0;
};

struct CosimReport {
  std::string target;
  std::map<std::string, CosimCheck> checks;     // per check id: what it compared and found
  std::uint64_t cycles = 0;                     // clock cycles simulated
  std::uint64_t transactions = 0;               // scoreboard transactions compared (RTL vs SystemC vs golden)
  std::uint64_t mismatches = 0;                 // total, including assertion failures
  std::vector<CosimMismatch> first_mismatches;  // at most kKeptMismatches
  std::uint64_t golden_checks = 0;              // reconstructed positions/ranges compared with the golden model
  int rtl_assertions_failed = 0;                // named SystemVerilog assertions that fired
  int sc_errors = 0;                            // SC_ERROR reports
  bool fault_injected = false;                  // the requested fault was applied somewhere
  std::string fault_site;                       // where it was applied (readable)
};

using CosimRunner = CosimReport (*)(const CosimOptions&);

struct CosimTarget {
  const char* name;                 // `rangesim cosim <name>`: a sensor id or a block name
  const char* description;          // one line for --help and `rangesim cosim --list`
  std::vector<std::string> faults;  // names accepted by --inject-fault, each must be caught
  CosimRunner run;
};

// All targets, sensors first. Defined in tb/common/cosim_targets.cpp.
const std::vector<CosimTarget>& cosim_targets();

}  // namespace rangesim::tb
