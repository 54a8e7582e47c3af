#pragma once
// The ls-conventional throughput figures of `rangesim bench` (docs/bench.md): the full range map
// (375 x 365 pixels, 375 frame accesses, four samplings) on the laser-sheet scene
// scenes/plane.toml, sparse against dense, against the uncertain-draw floor, against the verilated
// RTL of the readout, the SystemC module against its bare kernel, simulated time against CPU time,
// and the share of `simulate`'s wall time spent writing its outputs.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/bench/bench_pareto.h"

namespace rangesim::app::bench {

struct LsConventionalBenchOptions {
  bool quick = false;       // fewer frame accesses for the slow references (dense, SystemC, RTL)
  bool with_rtl = true;     // the verilated readout is built (RANGESIM_WITH_RTL)
  std::string scratch_dir;  // output folders of the child `simulate` runs (output_share); "" = skip
};

// Keys: sparse_vs_dense, floor_ratio, realtime_factor, systemc_vs_kernel, model_vs_rtl,
// output_share, each {value, target, ...details}; and "checks": {name: bool} for the identity checks.
nlohmann::json bench_ls_conventional(const LsConventionalBenchOptions& opt);

// The verilated readout as a row of the run-time-against-error table, scaled from the model's row
// (identical addresses, so the same error); nothing without an RTL figure.
void add_rtl_pareto_rows(const nlohmann::json& ls, std::vector<ParetoRow>& pareto);

}  // namespace rangesim::app::bench
