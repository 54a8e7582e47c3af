// The bench settings of tof-lockin: its rows of the run-time-against-error table (docs/bench.md).
#include <fmt/format.h>

#include "app/bench/bench_pareto.h"

namespace rangesim::app::bench {

std::vector<ParetoSetting> tof_lockin_pareto_settings(bool quick) {
  std::vector<ParetoSetting> s = {
      {"tof-lockin", "tof-lockin-plane.toml", "kernel, aggregated", "kernel", {"--kernel-only"}},
      {"tof-lockin", "tof-lockin-plane.toml", "SystemC module", "systemc", {}},
  };
  // The per-clock reference takes minutes: left out of --quick.
  if (!quick)
    s.push_back({"tof-lockin",
                 "tof-lockin-plane.toml",
                 "kernel, no aggregation",
                 "kernel",
                 {"--kernel-only", "--no-aggregate"}});
  // The pulse/gate overlaps integrated numerically at a time step (`simulate --time-step`) instead
  // of in closed form: 50 ns (half the preset's T0: the windows' charge is wrong by up to a step),
  // 10 ns and 0.1 ns (1000 steps per pulse); --quick leaves out the finest.
  for (const char* step : {"5e-08", "1e-08", "1e-10"}) {
    if (quick && std::string(step) == "1e-10") continue;
    s.push_back({"tof-lockin",
                 "tof-lockin-plane.toml",
                 fmt::format("kernel, aggregated, time step {} s", step),
                 "kernel",
                 {"--kernel-only", "--time-step", step}});
  }
  return s;
}

}  // namespace rangesim::app::bench
