// The bench settings of ls-demodulation: its rows of the run-time-against-error table (docs/bench.md).
#include <fmt/format.h>

#include "app/bench/bench_pareto.h"

namespace rangesim::app::bench {

std::vector<ParetoSetting> ls_demodulation_pareto_settings(bool quick) {
  std::vector<ParetoSetting> s = {
      {"ls-demodulation",
       "ls-demodulation-plane.toml",
       "kernel, event skipping, 1 frame",
       "kernel",
       {"--kernel-only", "--frames", "1"}},
      {"ls-demodulation",
       "ls-demodulation-plane.toml",
       "kernel, event skipping, 4 frames",
       "kernel",
       {"--kernel-only", "--frames", "4"}},
      {"ls-demodulation", "ls-demodulation-plane.toml", "SystemC module, 1 frame", "systemc", {"--frames", "1"}},
      {"ls-demodulation",
       "ls-demodulation-plane.toml",
       "kernel, per period (no aggregation)",
       "kernel",
       {"--kernel-only", "--no-aggregate", "--frames", "1"}},
  };
  // The per-clock reference takes minutes: left out of --quick.
  if (!quick)
    s.push_back({"ls-demodulation",
                 "ls-demodulation-plane.toml",
                 "kernel, per clock, 1 frame",
                 "kernel",
                 {"--kernel-only", "--no-event-skip", "--frames", "1"}});
  return s;
}

}  // namespace rangesim::app::bench
