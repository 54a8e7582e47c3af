#include "app/bench/bench_figures.h"

#include <cstdlib>

namespace rangesim::app::bench {

std::optional<bool> target_met(const std::string& target, const nlohmann::json& value) {
  if (!value.is_number() || target.size() < 4) return std::nullopt;
  const std::string op = target.substr(0, 2);
  if (op != ">=" && op != "<=") return std::nullopt;
  char* end = nullptr;
  const double x = std::strtod(target.c_str() + 2, &end);
  if (end == target.c_str() + 2) return std::nullopt;
  const double v = value.get<double>();
  return op == ">=" ? v >= x : v <= x;
}

const std::vector<FigureSpec>& all_figures() {
  static const std::vector<FigureSpec> all = [] {
    std::vector<FigureSpec> v;
    for (const auto* group : {&ls_conventional_figures(), &aggregation_figures(), &sparse_spad_figures(),
                              &monte_carlo_figures(), &numpy_peer_figures()})
      v.insert(v.end(), group->begin(), group->end());
    return v;
  }();
  return all;
}

}  // namespace rangesim::app::bench
