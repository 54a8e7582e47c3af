#include "core/params.h"

#include <cctype>
#include <cmath>
#include <cstdlib>
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
  if (it == values_.end()) throw UserError(fmt::format("{}: missing parameter '{}'", origin_, key), key);
  return it->second;
}

double ParamSet::real(const std::string& key) const { return at(key).number; }
long long ParamSet::integer(const std::string& key) const { return static_cast<long long>(at(key).number); }
const std::string& ParamSet::text(const std::string& key) const { return at(key).text; }
bool ParamSet::boolean(const std::string& key) const { return at(key).number != 0.0; }

void ParamSet::set_integer(const std::string& key, long long value, const std::string& flag,
                           const ParamSchema& schema) {
  const ParamSpec* spec = schema.find(key);
  if (!spec) throw UserError(fmt::format("{}: no parameter '{}' for sensor {}", flag, key, sensor_id_), key);
  check_range(*spec, static_cast<double>(value), flag);
  ParamValue& v = values_[key];
  v.kind = ParamKind::Integer;
  v.number = static_cast<double>(value);
  v.source = fmt::format("command line {}", flag);
  v.file = "command line";
}

void ParamSet::set_real(const std::string& key, double value, const std::string& flag, const ParamSchema& schema) {
  const ParamSpec* spec = schema.find(key);
  if (!spec) throw UserError(fmt::format("{}: no parameter '{}' for sensor {}", flag, key, sensor_id_), key);
  check_range(*spec, value, flag);
  ParamValue& v = values_[key];
  v.kind = ParamKind::Real;
  v.number = value;
  v.source = fmt::format("command line {}", flag);
  v.file = "command line";
}

void ParamSet::set_from_text(const std::string& assignment, const std::string& flag, const ParamSchema& schema) {
  const auto eq = assignment.find('=');
  if (eq == std::string::npos || eq == 0)
    throw UserError(fmt::format("{} {}: expected KEY=VALUE, e.g. {} timing.clock_Hz=50e6", flag, assignment, flag));
  const std::string key = assignment.substr(0, eq), text = assignment.substr(eq + 1);
  const std::string where = fmt::format("{} {}", flag, assignment);
  const ParamSpec* spec = schema.find(key);
  if (!spec)
    throw UserError(fmt::format("{}: no parameter '{}' for sensor {}; the keys are listed by `rangesim show {}`", where,
                                key, sensor_id_, sensor_id_),
                    key);
  ParamValue v;
  v.kind = spec->kind;
  v.source = fmt::format("command line {}", flag);
  v.file = "command line";
  char* end = nullptr;
  switch (spec->kind) {
    case ParamKind::Text:
      check_choice(*spec, text, where);
      v.text = text;
      break;
    case ParamKind::Boolean:
      if (text != "true" && text != "false")
        throw UserError(fmt::format("{}: {} must be true or false", where, key), key);
      v.number = text == "true" ? 1.0 : 0.0;
      break;
    case ParamKind::Real:
    case ParamKind::Integer:
      v.number = std::strtod(text.c_str(), &end);
      if (text.empty() || *end != '\0' || std::isspace(static_cast<unsigned char>(text[0])))
        throw UserError(fmt::format("{}: '{}' is not a number; allowed: {}", where, text, describe_range(*spec)), key);
      check_range(*spec, v.number, where);
      break;
  }
  values_[key] = v;
}

void check_choice(const ParamSpec& spec, const std::string& value, const std::string& where) {
  if (spec.choices.empty()) return;
  for (const auto& c : spec.choices)
    if (c == value) return;
  throw UserError(
      fmt::format("{}: {} = \"{}\" is not allowed; allowed: {}", where, spec.key, value, describe_range(spec)),
      spec.key);
}

std::string describe_range(const ParamSpec& spec) {
  switch (spec.kind) {
    case ParamKind::Text: {
      if (spec.choices.empty()) return "text";
      std::string s = "one of";
      for (const auto& c : spec.choices) s += " \"" + c + "\"";
      return s;
    }
    case ParamKind::Boolean: return "true or false";
    case ParamKind::Integer:
      return fmt::format("integer in {}{:g}, {:g}]", spec.min_exclusive ? "(" : "[", spec.min, spec.max);
    case ParamKind::Real:
      return fmt::format("{}{:g}, {:g}]{}", spec.min_exclusive ? "(" : "[", spec.min, spec.max,
                         spec.unit.empty() ? "" : " " + spec.unit);
  }
  return "";
}

namespace {

// The value as the message shows it: 6 digits where they are exact, all it needs otherwise, so a
// refused 1.0000001 never reads as the bound 1 it exceeds.
std::string shown(double value) {
  const std::string g = fmt::format("{:g}", value);
  return std::strtod(g.c_str(), nullptr) == value || !std::isfinite(value) ? g : fmt::format("{}", value);
}

}  // namespace

void check_range(const ParamSpec& spec, double value, const std::string& where) {
  if (spec.kind != ParamKind::Real && spec.kind != ParamKind::Integer) return;
  const bool ok = std::isfinite(value) && (spec.min_exclusive ? value > spec.min : value >= spec.min) &&
                  value <= spec.max && (spec.kind != ParamKind::Integer || value == std::floor(value));
  if (!ok)
    throw UserError(
        fmt::format("{}: {} = {} is out of range; allowed: {}", where, spec.key, shown(value), describe_range(spec)),
        spec.key);
}

}  // namespace rangesim
