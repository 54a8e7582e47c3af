// The bench settings of ls-conventional: its rows of the run-time-against-error table (docs/bench.md).
#include <fmt/format.h>

#include "app/bench/bench_pareto.h"

namespace rangesim::app::bench {

std::vector<ParetoSetting> ls_conventional_pareto_settings(bool quick) {
  // Frame accesses: a fifth of the map in the full run.
  const std::string lf = quick ? "25" : "75";
  return {
      {"ls-conventional", "plane.toml", "kernel, sparse, event skipping", "kernel", {"--kernel-only", "--frames", lf}},
      {"ls-conventional", "plane.toml", "kernel, dense", "kernel", {"--kernel-only", "--no-sparse", "--frames", lf}},
      {"ls-conventional",
       "plane.toml",
       "kernel, per clock",
       "kernel",
       {"--kernel-only", "--no-event-skip", "--frames", lf}},
      {"ls-conventional",
       "plane.toml",
       "kernel, noise-free",
       "kernel",
       {"--kernel-only", "--noise-free", "--frames", lf}},
      {"ls-conventional", "plane.toml", "SystemC module", "systemc", {"--frames", quick ? "10" : "60"}},
  };
}

}  // namespace rangesim::app::bench
