#pragma once
// The ls-conventional throughput figures of `rangesim bench` (docs/bench.md): the full range map
// (375 x 365 pixels, 375 frame accesses, four samplings) on the laser-sheet scene
// scenes/plane.toml, sparse against dense, against the touch limit, against the verilated RTL of
// the readout, the SystemC module against its bare kernel, and simulated time against wall time.
#include <nlohmann/json.hpp>

namespace rangesim::app::bench {

struct LsConventionalBenchOptions {
  bool quick = false;    // fewer frame accesses for the slow references (dense, SystemC, RTL)
  bool with_rtl = true;  // the verilated readout is built (RANGESIM_WITH_RTL)
};

// Keys: sparse_vs_dense, touch_limit_ratio, realtime_factor, systemc_vs_kernel, model_vs_rtl,
// each {value, target, ...details}; and "checks": {name: bool} for the identity checks.
nlohmann::json bench_ls_conventional(const LsConventionalBenchOptions& opt);

}  // namespace rangesim::app::bench
