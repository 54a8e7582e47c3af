#include "app/cli_common.h"

#include <cfloat>
#include <cmath>
#include <cstdlib>
#include <fmt/format.h>

#include "core/grid_rules.h"
#include "core/preset.h"
#include "core/user_error.h"

namespace rangesim::app {

namespace {

// The argument a flag sets, for UserError::key(): "--signal" -> "signal".
std::string key_of(const std::string& flag) { return flag.rfind("--", 0) == 0 ? flag.substr(2) : flag; }

double parse_number(const std::string& s, const std::string& flag, const std::string& text) {
  char* end = nullptr;
  const double v = std::strtod(s.c_str(), &end);
  if (s.empty() || *end != '\0')
    throw UserError(fmt::format("{} {}: '{}' is not a number; expected LO:HI:N, e.g. 0.001:1.5:61", flag, text, s),
                    key_of(flag));
  return v;
}

}  // namespace

GridAxis parse_grid_axis(const std::string& text, const std::string& flag) {
  const auto c1 = text.find(':');
  const auto c2 = c1 == std::string::npos ? std::string::npos : text.find(':', c1 + 1);
  if (c2 == std::string::npos || text.find(':', c2 + 1) != std::string::npos)
    throw UserError(fmt::format("{} {}: expected LO:HI:N (volts, log-spaced), e.g. 0.001:1.5:61", flag, text),
                    key_of(flag));
  GridAxis g;
  g.lo = parse_number(text.substr(0, c1), flag, text);
  g.hi = parse_number(text.substr(c1 + 1, c2 - c1 - 1), flag, text);
  const double n = parse_number(text.substr(c2 + 1), flag, text);
  if (!std::isfinite(g.lo) || !std::isfinite(g.hi))
    throw UserError(fmt::format("{} {}: LO and HI must be finite numbers; allowed: 0 < LO <= HI", flag, text),
                    key_of(flag));
  if (!(g.lo > 0))
    throw UserError(
        fmt::format("{} {}: LO = {:g} must be > 0 (log-spaced grid); allowed: 0 < LO <= HI", flag, text, g.lo),
        key_of(flag));
  if (g.lo > g.hi)
    throw UserError(fmt::format("{} {}: LO = {:g} > HI = {:g}; allowed: 0 < LO <= HI", flag, text, g.lo, g.hi),
                    key_of(flag));
  if (const std::string problem = log_grid_problem(g.lo, g.hi); !problem.empty())
    throw UserError(
        fmt::format("{} {}: the log-spaced grid has points that are not finite ({}); allowed: {} <= LO "
                    "and HI / LO <= {}",
                    flag, text, problem, DBL_MIN, DBL_MAX),
        key_of(flag));
  if (!(n >= 1 && n <= 10000 && n == std::floor(n)))
    throw UserError(fmt::format("{} {}: N = {:g} must be an integer in [1, 10000]", flag, text, n), key_of(flag));
  g.n = static_cast<int>(n);
  return g;
}

}  // namespace rangesim::app
