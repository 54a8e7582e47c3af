#include "app/bench/bench_groups.h"

#include "app/bench/bench_aggregation.h"
#include "app/bench/bench_figures.h"
#include "app/bench/bench_ls_conventional.h"
#include "app/bench/bench_numpy_peers.h"
#include "app/bench/bench_sparse_spad.h"
#include "app/bench/bench_util.h"
#include "app/bench/mc_bench_hook.h"

namespace rangesim::app::bench {

namespace {

using nlohmann::json;

// Each figure's details block under its key, from a group result keyed the same way.
void figures_from(const std::vector<FigureSpec>& figures, const json& result, json& details) {
  for (const auto& f : figures) details[f.key] = result[f.key];
}

json mc_hook_json(const McBenchHookResult& m) {
  return {{"mc_vs_bare_rng", m.mc_vs_bare_rng ? json(*m.mc_vs_bare_rng) : json(nullptr)},
          {"threads2_vs_1", m.threads2_vs_1 ? json(*m.threads2_vs_1) : json(nullptr)},
          {"details", m.details},
          {"note", m.note}};
}

}  // namespace

const std::vector<BenchGroup>& bench_groups() {
  static const std::vector<BenchGroup> groups = {
      {1000,
       [](const BenchGroupContext& c) {
         return bench_ls_conventional(LsConventionalBenchOptions{c.quick, RANGESIM_BENCH_HAS_RTL != 0, c.scratch_dir});
       },
       [](const json& r, json& details, json& checks) {
         figures_from(ls_conventional_figures(), r, details);
         for (const auto& [k, v] : r["checks"].items()) checks[k] = v;
       },
       add_rtl_pareto_rows},
      {1001, [](const BenchGroupContext& c) { return bench_aggregation_lockin(c.quick); },
       [](const json& r, json& details, json& checks) {
         details["aggregated_vs_per_clock_lockin"] = r;
         checks["lockin_aggregated_statistically_identical"] = r["statistically_identical"].get<bool>();
       },
       nullptr},
      {1003, [](const BenchGroupContext& c) { return bench_aggregation_spad(c.quick); },
       [](const json& r, json& details, json& checks) {
         details["aggregated_vs_per_clock_spad"] = r;
         checks["spad_aggregated_statistically_identical"] = r["statistically_identical"].get<bool>();
         checks["spad_per_clock_equals_per_cycle"] = r["per_clock_equals_per_cycle"].get<bool>();
       },
       nullptr},
      {1004, [](const BenchGroupContext& c) { return bench_sparse_spad(c.quick); },
       [](const json& r, json& details, json& checks) {
         details["sparse_vs_dense_spad"] = r;
         checks["spad_sparse_cycles_identical"] = r["cycles_identical"].get<bool>();
         checks["spad_sparse_lit_pixels_identical"] = r["lit_pixels_identical"].get<bool>();
         checks["spad_sparse_background_statistically_identical"] = r["background_statistically_identical"].get<bool>();
       },
       nullptr},
      {1005, [](const BenchGroupContext& c) { return bench_aggregation_demod(c.quick); },
       [](const json& r, json& details, json& checks) {
         details["aggregated_vs_per_clock_demod"] = r;
         checks["demod_aggregated_statistically_identical"] = r["statistically_identical"].get<bool>();
       },
       nullptr},
      {1002,
       [](const BenchGroupContext& c) {
         progress("Monte Carlo figures (sweep on 1 and 2 threads, bare variate loop)");
         return mc_hook_json(mc_bench_hook(c.quick));
       },
       [](const json& r, json& details, json& checks) {
         const std::string note = r["note"].get<std::string>();
         details["mc_vs_bare_rng"] = json{{"value", r["mc_vs_bare_rng"]}, {"note", note}};
         details["threads2_vs_1"] = json{{"value", r["threads2_vs_1"]}, {"note", note}};
         if (!r["details"].is_null()) details["monte_carlo"] = r["details"];
         // measure_mc_bench gives no speed-up when the 1- and 2-thread sweeps differ.
         checks["mc_threads_bit_identical"] = r["threads2_vs_1"].is_number();
       },
       nullptr},
      {1006, [](const BenchGroupContext& c) { return bench_numpy_peers(c.quick, c.scratch_dir); },
       [](const json& r, json& details, json&) { figures_from(numpy_peer_figures(), r, details); }, nullptr},
  };
  return groups;
}

}  // namespace rangesim::app::bench
