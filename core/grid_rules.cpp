#include "core/grid_rules.h"

#include <cfloat>
#include <cmath>
#include <fmt/format.h>

#include "core/user_error.h"

namespace rangesim {

namespace {

// The file the bad bound came from, or the flag that set it ("command line --set").
std::string where(const ParamSet& set, const std::string& lo_key, const std::string& hi_key) {
  for (const auto* key : {&lo_key, &hi_key}) {
    const ParamValue& v = set.at(*key);
    if (v.file == "command line") return v.source;
  }
  const std::string& file = set.at(lo_key).file;
  return file.empty() ? set.origin() : file;
}

}  // namespace

std::string log_grid_problem(double lo, double hi) {
  if (!(lo >= DBL_MIN)) return fmt::format("the minimum {} is below the smallest normal number {}", lo, DBL_MIN);
  if (!std::isfinite(hi / lo)) return fmt::format("the ratio max / min = {} / {} overflows to inf", hi, lo);
  return "";
}

void check_log_grids(const ParamSet& set) {
  for (const auto& [key, value] : set.values()) {
    const auto at = key.find("_min_");
    const bool axis = key.rfind("evaluation.signal_min_", 0) == 0 || key.rfind("evaluation.background_min_", 0) == 0;
    if (!axis || value.kind != ParamKind::Real) continue;
    const std::string max_key = key.substr(0, at) + "_max_" + key.substr(at + 5);
    if (!set.has(max_key)) continue;
    const double lo = value.number, hi = set.real(max_key);
    if (const std::string problem = log_grid_problem(lo, hi); !problem.empty())
      throw UserError(
          fmt::format("{}: {} = {} .. {} = {}: the log-spaced grid has points that are not finite ({}); "
                      "allowed: {} <= min and max / min <= {}",
                      where(set, key, max_key), key, lo, max_key, hi, problem, DBL_MIN, DBL_MAX));
  }
}

}  // namespace rangesim
