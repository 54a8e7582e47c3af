// CONNECT AT MERGE (lead): replace the body with
//   #include "app/bench_mc.h"
//   const McBenchFigures f = measure_mc_bench(quick);
//   return {f.<mc_vs_bare_rng field>, f.<threads2_vs_1 field>, <details as json>, ""};
// (field names from app/bench_mc.h on branch issue6mc).
#include "app/bench/mc_bench_hook.h"

namespace rangesim::app::bench {

McBenchHookResult mc_bench_hook(bool /*quick*/) {
  McBenchHookResult r;
  r.note = "not connected: measured by the Monte Carlo evaluation (measure_mc_bench, app/bench_mc.h, branch issue6mc); "
           "the lead connects it in app/bench/mc_bench_hook.cpp at merge";
  return r;
}

}  // namespace rangesim::app::bench
