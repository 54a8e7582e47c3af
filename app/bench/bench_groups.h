#pragma once
// The figure groups of `rangesim bench` in the order they run: each one measures its figures
// (journaled by the command under its own index, so --resume takes it back exactly) and then puts
// them into bench.json's details and checks. The command loops over this list and never names a
// sensor; what a group measures and on which sensor lives in its own file (app/bench/bench_*.cpp).
#include <functional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/bench/bench_pareto.h"

namespace rangesim::app::bench {

struct BenchGroupContext {
  bool quick = false;       // --quick
  std::string scratch_dir;  // output folders of child runs
};

struct BenchGroup {
  long long journal_index;  // its record in the bench journal (Pareto rows use 0, 1, ...)
  std::function<nlohmann::json(const BenchGroupContext&)> measure;
  // details.<key> for each of its figures and its identity checks, from what measure returned.
  std::function<void(const nlohmann::json& result, nlohmann::json& details, nlohmann::json& checks)> collect;
  // Rows the group adds to the run-time-against-error table (may be empty).
  std::function<void(const nlohmann::json& result, std::vector<ParetoRow>& pareto)> pareto_rows;
};

const std::vector<BenchGroup>& bench_groups();

}  // namespace rangesim::app::bench
