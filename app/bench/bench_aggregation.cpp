// What the aggregation figures share (app/bench/bench_aggregation.h); each sensor's figure is in
// app/bench/aggregation_<sensor>.cpp.
#include "app/bench/bench_aggregation.h"

#include "app/bench/bench_figures.h"

namespace rangesim::app::bench {

using nlohmann::json;

const std::vector<FigureSpec>& aggregation_figures() {
  static const std::vector<FigureSpec> f = {
      {"aggregated_vs_per_clock_lockin", ">= 1000",
       "tof-lockin per-clock frame time / aggregated frame time, statistically identical"},
      {"aggregated_vs_per_clock_spad", ">= 1000",
       "tof-spad per-clock frame time / aggregated frame time, statistically identical"},
      {"aggregated_vs_per_clock_demod", ">= 1000",
       "ls-demodulation per-period frame time / aggregated frame time (N = 10,000 periods), statistically "
       "identical"},
  };
  return f;
}

json comparison_json(const TwoSampleComparison& c) {
  return json{{"mean_aggregated_V", c.mean_a},
              {"mean_per_clock_V", c.mean_b},
              {"var_aggregated_V2", c.var_a},
              {"var_per_clock_V2", c.var_b},
              {"mean_z", c.mean_z},
              {"var_z", c.var_z},
              {"ks_d", c.ks_d},
              {"ks_p", c.ks_p},
              {"indistinguishable", c.indistinguishable()}};
}

}  // namespace rangesim::app::bench
