// What the aggregation figures share (app/bench/bench_aggregation.h); each sensor's figure is in
// app/bench/aggregation_<sensor>.cpp.
#include "app/bench/bench_aggregation.h"

#include "app/bench/bench_figures.h"

namespace rangesim::app::bench {

using nlohmann::json;

const std::vector<FigureSpec>& aggregation_figures() {
  static const std::vector<FigureSpec> f = {aggregation_figure_lockin(), aggregation_figure_spad(),
                                            aggregation_figure_demod()};
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
