// The Monte Carlo figures come from the Monte Carlo evaluation's own measurement
// (app/bench_mc.h), so the bench and `rangesim-bench-mc` report the same thing.
#include "app/bench/mc_bench_hook.h"

#include <exception>

#include "app/bench/bench_figures.h"
#include "app/bench_mc.h"

namespace rangesim::app::bench {

const std::vector<FigureSpec>& monte_carlo_figures() {
  static const std::vector<FigureSpec> f = {
      {"mc_vs_bare_rng", ">= 0.5", "Monte Carlo sweep variates per second / bare loop drawing them"},
      {"threads2_vs_1", ">= 1.8", "Monte Carlo sweep time with 1 thread / with 2 threads"},
  };
  return f;
}

McBenchHookResult mc_bench_hook(bool quick) {
  McBenchHookResult r;
  try {
    const McBenchFigures f = measure_mc_bench(quick);
    r.mc_vs_bare_rng = f.mc_vs_bare_rng;
    r.threads2_vs_1 = f.threads2_vs_1;
    r.details = {{"mc_variates_per_s", f.mc_variates_per_s},     {"bare_variates_per_s", f.bare_variates_per_s},
                 {"sweep_1thread_s", f.sweep_1thread_s},         {"sweep_2threads_s", f.sweep_2threads_s},
                 {"sweep_1thread_cpu_s", f.sweep_1thread_cpu_s}, {"sweep_2threads_cpu_s", f.sweep_2threads_cpu_s},
                 {"cpu_share_2threads", f.cpu_share_2threads},   {"cpu_2threads_vs_1", f.cpu_2threads_vs_1},
                 {"load_average_1min", f.load_average_1min},     {"threads_identical", true}};
  } catch (const std::exception& e) {
    // measure_mc_bench throws when the 1- and 2-thread sweeps differ: an identity failure.
    r.note = e.what();
  }
  return r;
}

}  // namespace rangesim::app::bench
