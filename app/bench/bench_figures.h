#pragma once
// The throughput figures of `rangesim bench` with their targets (docs/bench.md). Each figure group
// (app/bench/bench_*.cpp) declares its own figures next to the code that measures them; the
// command only collects them in order, so it never names a sensor.
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace rangesim::app::bench {

struct FigureSpec {
  const char* key;      // top-level key of bench.json; details under details.<key>
  const char* target;   // ">= X", "<= X" (a met flag) or "report ..." (no flag)
  const char* meaning;  // one line for figures.md
};

// Whether `value` meets `target` (">= X" / "<= X"); nullopt for a report-only target or a
// missing value (null).
std::optional<bool> target_met(const std::string& target, const nlohmann::json& value);

// Every figure of every group, in the order bench.json and figures.md list them.
const std::vector<FigureSpec>& all_figures();

// The groups' own lists (defined beside each group).
const std::vector<FigureSpec>& ls_conventional_figures();  // bench_ls_conventional.cpp
const std::vector<FigureSpec>& aggregation_figures();      // bench_aggregation.cpp
const std::vector<FigureSpec>& sparse_spad_figures();      // bench_sparse_spad.cpp
const std::vector<FigureSpec>& monte_carlo_figures();      // mc_bench_hook.cpp
const std::vector<FigureSpec>& numpy_peer_figures();       // bench_numpy_peers.cpp

}  // namespace rangesim::app::bench
