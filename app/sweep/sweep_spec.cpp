#include "app/sweep/sweep_spec.h"

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>

#include "core/user_error.h"

namespace rangesim::app::sweep {

namespace {

std::vector<std::string> split(const std::string& s, char sep) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  for (std::size_t i = 0; i <= s.size(); ++i)
    if (i == s.size() || s[i] == sep) parts.push_back(s.substr(start, i - start)), start = i + 1;
  return parts;
}

double number(const std::string& text, const std::string& where) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || *end != '\0' || !std::isfinite(v))
    throw UserError(
        fmt::format("{}: '{}' is not a finite number; expected KEY=LO:HI:N[:log] or KEY=v1,v2,...", where, text));
  return v;
}

// LO:HI:N[:log] -> N values from LO to HI (both ends included).
std::vector<double> range_values(const std::vector<std::string>& f, const std::string& where) {
  const double lo = number(f[0], where), hi = number(f[1], where), n = number(f[2], where);
  const bool log = f.size() == 4;
  if (f.size() == 4 && f[3] != "log")
    throw UserError(fmt::format("{}: the fourth field must be 'log' (log-spaced); got '{}'", where, f[3]));
  if (!(n >= 1 && n <= 100000 && n == std::floor(n)))
    throw UserError(fmt::format("{}: N = {:g} must be an integer in [1, 100000]", where, n));
  if (lo > hi) throw UserError(fmt::format("{}: LO = {:g} > HI = {:g}; allowed LO <= HI", where, lo, hi));
  if (log && !(lo > 0)) throw UserError(fmt::format("{}: a log-spaced range needs LO > 0; got {:g}", where, lo));
  std::vector<double> v;
  const int count = static_cast<int>(n);
  for (int i = 0; i < count; ++i) {
    const double t = count == 1 ? 0.0 : static_cast<double>(i) / (count - 1);
    v.push_back(i == count - 1 ? hi : log ? lo * std::pow(hi / lo, t) : lo + (hi - lo) * t);
  }
  return v;
}

}  // namespace

VaryAxis parse_vary(const std::string& spec, const ParamSchema& schema) {
  const std::string where = "--vary " + spec;
  const auto eq = spec.find('=');
  if (eq == std::string::npos || eq == 0 || eq + 1 == spec.size())
    throw UserError(fmt::format("{}: expected KEY=LO:HI:N[:log] or KEY=v1,v2,...", where));
  VaryAxis axis{spec.substr(0, eq), {}};
  const ParamSpec* p = schema.find(axis.key);
  if (!p)
    throw UserError(fmt::format("{}: no parameter '{}' for sensor {}; the keys are listed by `rangesim show {}`", where,
                                axis.key, schema.sensor_id, schema.sensor_id));
  const std::string rhs = spec.substr(eq + 1);
  const std::vector<std::string> fields = split(rhs, ':');
  const bool numeric = p->kind == ParamKind::Real || p->kind == ParamKind::Integer;
  if (fields.size() == 3 || fields.size() == 4) {
    if (!numeric) throw UserError(fmt::format("{}: {} is not a number; give a list v1,v2,...", where, axis.key));
    for (double v : range_values(fields, where)) {
      const std::string text =
          p->kind == ParamKind::Integer ? fmt::format("{}", std::llround(v)) : fmt::format("{:.17g}", v);
      if (axis.values.empty() || axis.values.back() != text) axis.values.push_back(text);
    }
  } else if (fields.size() == 1) {
    for (const auto& v : split(rhs, ','))
      if (v.empty())
        throw UserError(fmt::format("{}: an empty value in the list", where));
      else
        axis.values.push_back(v);
  } else {
    throw UserError(fmt::format("{}: expected KEY=LO:HI:N[:log] or KEY=v1,v2,...", where));
  }
  // Each value must be a legal value of its key on its own (type, range, choices): exit 2 here,
  // not an invalid row; only the cross-key checks make rows invalid.
  ParamSet scratch("", schema.sensor_id);
  for (const auto& v : axis.values) scratch.set_from_text(axis.key + "=" + v, "--vary", schema);
  return axis;
}

std::vector<std::vector<std::string>> variants(const std::vector<VaryAxis>& axes, bool zip, long long max_variants) {
  std::vector<std::vector<std::string>> out;
  if (axes.empty()) return {{}};
  if (zip) {
    for (const auto& a : axes)
      if (a.values.size() != axes.front().values.size())
        throw UserError(fmt::format("--zip: --vary {} has {} values and --vary {} has {}; allowed: the same number",
                                    axes.front().key, axes.front().values.size(), a.key, a.values.size()));
    for (std::size_t i = 0; i < axes.front().values.size(); ++i) {
      std::vector<std::string> v;
      for (const auto& a : axes) v.push_back(a.key + "=" + a.values[i]);
      out.push_back(v);
    }
    return out;
  }
  long double total = 1;
  for (const auto& a : axes) total *= static_cast<long double>(a.values.size());
  if (total > max_variants)
    throw UserError(
        fmt::format("--vary: {:.0Lf} variants; allowed at most {} (fewer values, or --zip)", total, max_variants));
  out.push_back({});
  for (const auto& a : axes) {
    std::vector<std::vector<std::string>> next;
    for (const auto& prefix : out)
      for (const auto& value : a.values) {
        auto v = prefix;
        v.push_back(a.key + "=" + value);
        next.push_back(std::move(v));
      }
    out = std::move(next);
  }
  return out;
}

}  // namespace rangesim::app::sweep
