#include "core/params.h"

#include <cmath>
#include <fmt/format.h>

#include "core/user_error.h"

namespace rangesim {

const ParamSpec* ParamSchema::find(const std::string& key) const {
  for (const auto& p : params)
    if (p.key == key) return &p;
  return nullptr;
}

const ParamValue& ParamSet::at(const std::string& key) const {
  auto it = values_.find(key);
  if (it == values_.end()) throw UserError(fmt::format("{}: missing parameter '{}'", origin_, key));
  return it->second;
}

double ParamSet::real(const std::string& key) const { return at(key).number; }
long long ParamSet::integer(const std::string& key) const { return static_cast<long long>(at(key).number); }
const std::string& ParamSet::text(const std::string& key) const { return at(key).text; }
bool ParamSet::boolean(const std::string& key) const { return at(key).number != 0.0; }

void ParamSet::set_integer(const std::string& key, long long value, const std::string& flag,
                           const ParamSchema& schema) {
  const ParamSpec* spec = schema.find(key);
  if (!spec) throw UserError(fmt::format("{}: no parameter '{}' for sensor {}", flag, key, sensor_id_));
  check_range(*spec, static_cast<double>(value), flag);
  ParamValue& v = values_[key];
  v.kind = ParamKind::Integer;
  v.number = static_cast<double>(value);
  v.source = fmt::format("command line {}", flag);
}

void ParamSet::set_real(const std::string& key, double value, const std::string& flag, const ParamSchema& schema) {
  const ParamSpec* spec = schema.find(key);
  if (!spec) throw UserError(fmt::format("{}: no parameter '{}' for sensor {}", flag, key, sensor_id_));
  check_range(*spec, value, flag);
  ParamValue& v = values_[key];
  v.kind = ParamKind::Real;
  v.number = value;
  v.source = fmt::format("command line {}", flag);
}

std::string describe_range(const ParamSpec& spec) {
  switch (spec.kind) {
    case ParamKind::Text: {
      if (spec.choices.empty()) return "text";
      std::string s = "one of";
      for (const auto& c : spec.choices) s += " \"" + c + "\"";
      return s;
    }
    case ParamKind::Boolean:
      return "true or false";
    case ParamKind::Integer:
      return fmt::format("integer in {}{:g}, {:g}]", spec.min_exclusive ? "(" : "[", spec.min, spec.max);
    case ParamKind::Real:
      return fmt::format("{}{:g}, {:g}]{}", spec.min_exclusive ? "(" : "[", spec.min, spec.max,
                         spec.unit.empty() ? "" : " " + spec.unit);
  }
  return "";
}

void check_range(const ParamSpec& spec, double value, const std::string& where) {
  if (spec.kind != ParamKind::Real && spec.kind != ParamKind::Integer) return;
  const bool ok = std::isfinite(value) && (spec.min_exclusive ? value > spec.min : value >= spec.min) &&
                  value <= spec.max && (spec.kind != ParamKind::Integer || value == std::floor(value));
  if (!ok)
    throw UserError(fmt::format("{}: {} = {:g} is out of range; allowed: {}", where, spec.key, value,
                                describe_range(spec)));
}

}  // namespace rangesim
