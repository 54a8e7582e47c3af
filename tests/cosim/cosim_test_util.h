#pragma once
// What the co-simulation test files share: the one-elaboration-per-process guard (one flag for
// the whole binary), a report's mismatches as text, and a summary line for the ctest log.
#include <cstdio>
#include <string>

#include "../systemc/elaboration_guard.h"
#include "tb/common/cosim_scoreboard.h"
#include "tb/common/cosim_target.h"

namespace rangesim::tb::test {

inline std::string text(const CosimReport& r) {
  std::string s;
  for (const auto& m : r.first_mismatches) s += CosimScoreboard::format(m) + "\n";
  return s;
}

inline void print_summary(const CosimReport& r) {
  std::printf("%s: %llu cycles, %llu transactions, %llu golden checks, %llu mismatches\n", r.target.c_str(),
              static_cast<unsigned long long>(r.cycles), static_cast<unsigned long long>(r.transactions),
              static_cast<unsigned long long>(r.golden_checks), static_cast<unsigned long long>(r.mismatches));
}

}  // namespace rangesim::tb::test
