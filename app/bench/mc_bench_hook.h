#pragma once
// Hook for the two Monte Carlo figures of `rangesim bench` (mc_vs_bare_rng, threads2_vs_1),
// measured by the Monte Carlo evaluation (`measure_mc_bench(bool quick)` in app/bench_mc.h);
// a note says why a value is missing (the 1- and 2-thread sweeps differed).
#include <optional>
#include <string>

#include <nlohmann/json.hpp>

namespace rangesim::app::bench {

struct McBenchHookResult {
  std::optional<double> mc_vs_bare_rng;  // random variates per second in the sweep / bare loop (target >= 0.5)
  std::optional<double> threads2_vs_1;   // sweep speed-up with 2 threads over 1 (target >= 1.8)
  nlohmann::json details;                // whatever the measurement reports beside the ratios
  std::string note;                      // why a value is missing
};

// The only place the bench calls measure_mc_bench.
McBenchHookResult mc_bench_hook(bool quick);

}  // namespace rangesim::app::bench
