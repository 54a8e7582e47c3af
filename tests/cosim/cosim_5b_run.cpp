// Runs one issue-5b co-simulation target with a chosen cycle count, seed and fault and prints
// its report (the measurements of the closing note; `rangesim cosim` will call the same
// runners). Usage: cosim_5b_run <target> [cycles] [seed] [fault]. Exit 0 when the run is clean
// (or, with a fault, when the fault was caught), 1 otherwise, 2 on bad arguments.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <systemc>

#include "tb/common/cosim_scoreboard.h"
#include "tb/common/cosim_target.h"

int sc_main(int argc, char* argv[]) {
  const auto& targets = rangesim::tb::cosim_targets();
  const rangesim::tb::CosimTarget* t = nullptr;
  for (const auto& x : targets)
    if (argc > 1 && argv[1] == std::string(x.name)) t = &x;
  if (!t) {
    std::fprintf(stderr, "usage: %s <target> [cycles] [seed] [fault]; targets:\n", argv[0]);
    for (const auto& x : targets) std::fprintf(stderr, "  %-22s %s\n", x.name, x.description);
    return 2;
  }
  rangesim::tb::CosimOptions o;
  if (argc > 2) o.cycles = std::strtoull(argv[2], nullptr, 10);
  if (argc > 3) o.seed = std::strtoull(argv[3], nullptr, 10);
  if (argc > 4) o.inject_fault = argv[4];
  if (!o.inject_fault.empty()) {
    bool known = false;
    for (const auto& f : t->faults) known = known || f == o.inject_fault;
    if (!known) {
      std::fprintf(stderr, "unknown fault '%s' for %s\n", o.inject_fault.c_str(), t->name);
      return 2;
    }
  }
  sc_core::sc_report_handler::set_actions(sc_core::SC_ERROR, sc_core::SC_DO_NOTHING);
  const auto t0 = std::chrono::steady_clock::now();
  const rangesim::tb::CosimReport r = t->run(o);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  std::printf(
      "target %s seed %llu fault %s: cycles %llu transactions %llu golden_checks %llu "
      "mismatches %llu rtl_assertions %d wall %.2f s\n",
      r.target.c_str(), static_cast<unsigned long long>(o.seed),
      o.inject_fault.empty() ? "none" : o.inject_fault.c_str(), static_cast<unsigned long long>(r.cycles),
      static_cast<unsigned long long>(r.transactions), static_cast<unsigned long long>(r.golden_checks),
      static_cast<unsigned long long>(r.mismatches), r.rtl_assertions_failed, wall);
  for (const auto& m : r.first_mismatches) std::printf("  %s\n", rangesim::tb::CosimScoreboard::format(m).c_str());
  if (!o.inject_fault.empty()) {
    std::printf("fault %s at %s: %s\n", o.inject_fault.c_str(), r.fault_site.c_str(),
                r.fault_injected && r.mismatches > 0 ? "CAUGHT" : "MISSED");
    return r.fault_injected && r.mismatches > 0 ? 0 : 1;
  }
  return r.mismatches == 0 && r.rtl_assertions_failed == 0 ? 0 : 1;
}
