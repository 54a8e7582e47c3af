#pragma once
// Schema-checked parameter sets loaded from preset TOML files.
//
// A preset is a set of sections; every parameter is an inline table
//   integration_time_s = { value = 50e-6, source = "thesis Table 3.1" }
// whose key carries its SI unit. A ParamSchema (one per sensor id) lists every allowed key with
// its type, unit, allowed range and meaning; loading checks the file against it and throws
// UserError naming file, key and allowed range on any violation.
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace rangesim {

enum class ParamKind { Real, Integer, Text, Boolean };

struct ParamSpec {
  std::string key;   // "section.name", name ends in its SI unit where it has one
  ParamKind kind;    // value type in the TOML file
  std::string unit;  // SI unit for display ("s", "F", "V", "" for dimensionless)
  double min = 0.0;  // allowed range (Real/Integer)
  double max = 0.0;
  bool min_exclusive = false;             // true: value must be > min (e.g. capacitance > 0)
  std::string description;                // one line, shown by `rangesim show`
  std::vector<std::string> choices = {};  // allowed values (Text); empty = any
};

struct ParamSchema {
  std::string sensor_id;
  std::vector<ParamSpec> params;
  const ParamSpec* find(const std::string& key) const;
};

struct ParamValue {
  ParamKind kind = ParamKind::Real;
  double number = 0.0;  // Real, Integer (exact up to 2^53) and Boolean (0/1)
  std::string text;     // Text
  std::string source;   // where the number comes from: thesis table/eq., paper, derived, assumed, user
  std::string file;     // the preset file that set it ("command line" for --set and flags)
};

class ParamSet {
 public:
  ParamSet() = default;
  ParamSet(std::string origin, std::string sensor_id) : origin_(std::move(origin)), sensor_id_(std::move(sensor_id)) {}

  double real(const std::string& key) const;
  long long integer(const std::string& key) const;
  const std::string& text(const std::string& key) const;
  bool boolean(const std::string& key) const;
  const ParamValue& at(const std::string& key) const;
  bool has(const std::string& key) const { return values_.count(key) != 0; }

  // Overrides one value (command-line flag); `flag` names the option for error messages.
  void set_integer(const std::string& key, long long value, const std::string& flag, const ParamSchema& schema);
  void set_real(const std::string& key, double value, const std::string& flag, const ParamSchema& schema);
  // Overrides one value from "KEY=VALUE" text (`--set`), parsed by the key's type and checked like
  // a preset value; `flag` names the option in messages.
  void set_from_text(const std::string& assignment, const std::string& flag, const ParamSchema& schema);

  const std::map<std::string, ParamValue>& values() const { return values_; }
  std::map<std::string, ParamValue>& mutable_values() { return values_; }
  const std::string& origin() const { return origin_; }  // file the set was loaded from
  const std::string& sensor_id() const { return sensor_id_; }

 private:
  std::string origin_;
  std::string sensor_id_;
  std::map<std::string, ParamValue> values_;
};

// Checks a number against a spec; throws UserError "<where>: <key> = v is out of range [..]".
void check_range(const ParamSpec& spec, double value, const std::string& where);

// Checks a text value against a spec's choices; throws UserError naming the allowed values.
void check_choice(const ParamSpec& spec, const std::string& value, const std::string& where);

// Text for the allowed range of a spec, e.g. "(0, 1e-3] s" or "integer in [1, 64]".
std::string describe_range(const ParamSpec& spec);

}  // namespace rangesim
