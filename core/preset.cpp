#include "core/preset.h"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fmt/format.h>
#include <optional>
#include <toml++/toml.h>

#include "core/grid_rules.h"
#include "core/input_file.h"
#include "core/user_error.h"

#ifndef RANGESIM_SOURCE_PRESET_DIR
#define RANGESIM_SOURCE_PRESET_DIR ""
#endif
#ifndef RANGESIM_INSTALL_PRESET_DIR
#define RANGESIM_INSTALL_PRESET_DIR ""
#endif

namespace fs = std::filesystem;

namespace rangesim {

namespace {
// A preset is a few kilobytes; the cap keeps a mistaken path (a log, an image) from being read whole.
constexpr std::uintmax_t kMaxPresetBytes = 4u << 20;
}  // namespace

std::vector<std::string> preset_search_path() {
  std::vector<std::string> dirs;
  if (const char* env = std::getenv("RANGESIM_PRESET_DIR"); env && *env) dirs.emplace_back(env);
  // Installed layout: <prefix>/bin/rangesim -> <prefix>/share/rangesim/presets.
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) dirs.push_back((exe.parent_path().parent_path() / "share/rangesim/presets").string());
  if (*RANGESIM_INSTALL_PRESET_DIR) dirs.emplace_back(RANGESIM_INSTALL_PRESET_DIR);
  if (*RANGESIM_SOURCE_PRESET_DIR) dirs.emplace_back(RANGESIM_SOURCE_PRESET_DIR);
  return dirs;
}

std::string resolve_preset(const std::string& id_or_path) {
  const bool looks_like_path = id_or_path.find('/') != std::string::npos ||
                               (id_or_path.size() > 5 && id_or_path.substr(id_or_path.size() - 5) == ".toml");
  if (looks_like_path) {
    check_readable(id_or_path, "preset file", kMaxPresetBytes);
    return id_or_path;
  }
  for (const auto& dir : preset_search_path()) {
    const fs::path p = fs::path(dir) / (id_or_path + ".toml");
    if (unreadable_reason(p.string()).empty()) return p.string();
  }
  throw UserError(fmt::format("'{}' is neither a preset nor a file; presets: {} (or a path to a .toml file)",
                              id_or_path, sensor_ids()));
}

namespace {

std::string where_of(const std::string& file, const toml::node& node) {
  const auto& src = node.source();
  if (src.begin.line == 0) return file;
  return fmt::format("{}:{}", file, src.begin.line);
}

// The value of `entry`: an inline table { value = ..., source = "..." }, or a plain value (a
// user's edit), whose source is "user".
ParamValue read_value(const std::string& file, const std::string& key, const toml::node& entry, const ParamSpec& spec) {
  const std::string where = where_of(file, entry);
  const toml::table* t = entry.as_table();
  const toml::node* value = &entry;
  ParamValue v;
  v.kind = spec.kind;
  v.source = "user";
  v.file = file;
  if (t) {
    if (!t->contains("value") || !t->contains("source"))
      throw UserError(fmt::format("{}: {} must be a plain value or an inline table {{ value = ..., source = \"...\" }} "
                                  "with value {}",
                                  where, key, describe_range(spec)),
                      key);
    for (const auto& [k, _] : *t)
      if (k != "value" && k != "source")
        throw UserError(fmt::format("{}: {} has unknown field '{}'; allowed: value, source", where, key, k.str()), key);
    const auto* source = (*t)["source"].as_string();
    if (!source || source->get().empty())
      throw UserError(
          fmt::format("{}: {}.source must be a non-empty string naming where the value comes from", where, key), key);
    v.source = source->get();
    value = t->get("value");
  }
  switch (spec.kind) {
    case ParamKind::Real:
      if (auto d = value->value_exact<double>())
        v.number = *d;
      else if (auto i = value->value_exact<int64_t>())
        v.number = static_cast<double>(*i);
      else
        throw UserError(fmt::format("{}: {} must be a number ({})", where, key, describe_range(spec)), key);
      break;
    case ParamKind::Integer:
      if (auto i = value->value_exact<int64_t>())
        v.number = static_cast<double>(*i);
      else
        throw UserError(fmt::format("{}: {} must be an integer ({})", where, key, describe_range(spec)), key);
      break;
    case ParamKind::Boolean:
      if (auto b = value->value_exact<bool>())
        v.number = *b ? 1.0 : 0.0;
      else
        throw UserError(fmt::format("{}: {} must be true or false", where, key), key);
      break;
    case ParamKind::Text:
      if (auto s = value->value_exact<std::string>())
        v.text = *s;
      else
        throw UserError(fmt::format("{}: {} must be a string ({})", where, key, describe_range(spec)), key);
      check_choice(spec, v.text, where);
      break;
  }
  check_range(spec, v.number, where);
  return v;
}

std::string read_file(const std::string& path) { return read_input_file(path, "preset file", kMaxPresetBytes); }

// The file `base = "..."` names: a preset id, or a path relative to the inheriting file's folder.
std::string resolve_base(const std::string& base, const std::string& file, const std::string& where) {
  const bool looks_like_path =
      base.find('/') != std::string::npos || (base.size() > 5 && base.compare(base.size() - 5, 5, ".toml") == 0);
  if (!looks_like_path) {
    try {
      return resolve_preset(base);
    } catch (const UserError& e) {
      throw UserError(fmt::format("{}: base = \"{}\": {}", where, base, e.what()), e.key());
    }
  }
  fs::path p(base);
  if (p.is_relative()) p = fs::path(file).parent_path() / p;
  const std::string reason = unreadable_reason(p.string());
  if (reason == "no such file")
    throw UserError(fmt::format("{}: base = \"{}\": no such preset file ({})", where, base, p.string()));
  if (!reason.empty())
    throw UserError(fmt::format("{}: base = \"{}\": cannot read preset file {}: {}", where, base, p.string(), reason));
  return p.string();
}

ParamSet load_layer(const std::string& text, const std::string& path, std::vector<std::string>& chain);

// The preset `base` names, loaded with the chain of files that inherit from it (a circle is
// refused, naming the files).
ParamSet load_base(const toml::node& base_node, const std::string& path, std::vector<std::string>& chain) {
  const std::string where = where_of(path, base_node);
  const auto* base = base_node.as_string();
  if (!base || base->get().empty())
    throw UserError(fmt::format("{}: base must be a preset id or a path to a preset file, as a string", where));
  const std::string file = resolve_base(base->get(), path, where);
  std::error_code ec;
  const std::string canonical = fs::weakly_canonical(file, ec).string();
  for (const auto& c : chain)
    if (c == canonical) {
      std::string circle;
      for (const auto& x : chain) circle += x + " -> ";
      throw UserError(
          fmt::format("{}: base = \"{}\" inherits in a circle: {}{}", where, base->get(), circle, canonical));
    }
  chain.push_back(canonical);
  ParamSet set = load_layer(read_file(file), file, chain);
  chain.pop_back();
  return set;
}

std::string unknown_key_message(const std::string& where, const std::string& key, const std::string& section,
                                const ParamSchema& schema) {
  std::string allowed;
  if (section == "sensor") allowed = "sensor.id";
  for (const auto& p : schema.params)
    if (p.key.rfind(section + ".", 0) == 0) allowed += (allowed.empty() ? "" : ", ") + p.key;
  return fmt::format("{}: unknown key '{}' for sensor {}; allowed in [{}]: {}", where, key, schema.sensor_id, section,
                     allowed.empty() ? "(no such section)" : allowed);
}

// One file of a preset: its base (if any) with this file's values laid over it. Every key must
// be known; without a base every key must be present.
ParamSet load_layer(const std::string& text, const std::string& path, std::vector<std::string>& chain) {
  toml::table root;
  try {
    root = toml::parse(text, path);
  } catch (const toml::parse_error& e) {
    throw UserError(fmt::format("{}:{}:{}: TOML syntax error: {}", path, e.source().begin.line, e.source().begin.column,
                                e.description()));
  }
  std::optional<ParamSet> base;
  if (const toml::node* b = root.get("base")) base = load_base(*b, path, chain);
  const auto* id = root["sensor"]["id"].as_string();
  if (!id && root["sensor"]["id"])
    throw UserError(fmt::format("{}: sensor.id must be a string; allowed: {}",
                                where_of(path, *root["sensor"]["id"].node()), sensor_ids()));
  if (!id && !base)
    throw UserError(fmt::format("{}: missing key sensor.id; allowed: {} (or base = \"<preset>\")", path, sensor_ids()));
  if (id && base && id->get() != base->sensor_id())
    throw UserError(fmt::format("{}: sensor.id = \"{}\" differs from its base's sensor {}; allowed: {} or no sensor.id",
                                where_of(path, *root["sensor"]["id"].node()), id->get(), base->sensor_id(),
                                base->sensor_id()));
  const std::string sensor = id ? id->get() : base->sensor_id();
  const ParamSchema& schema = schema_for(sensor, path);
  ParamSet set(path, sensor);
  if (base) set.mutable_values() = base->values();

  for (const auto& [section_key, section_node] : root) {
    const std::string section = std::string(section_key.str());
    if (section == "base") continue;
    const toml::table* section_table = section_node.as_table();
    if (!section_table)
      throw UserError(fmt::format("{}: top-level key '{}' must be a [section] (or base = \"<preset>\")",
                                  where_of(path, section_node), section));
    for (const auto& [name_key, entry] : *section_table) {
      const std::string key = section + "." + std::string(name_key.str());
      if (key == "sensor.id") continue;
      const ParamSpec* spec = schema.find(key);
      if (!spec) throw UserError(unknown_key_message(where_of(path, entry), key, section, schema), key);
      set.mutable_values()[key] = read_value(path, key, entry, *spec);
    }
  }
  for (const auto& spec : schema.params)
    if (!set.has(spec.key))
      throw UserError(
          fmt::format("{}: missing key '{}' ({}; {})", path, spec.key, spec.description, describe_range(spec)),
          spec.key);
  return set;
}

}  // namespace

ParamSet load_preset_file(const std::string& path) { return load_preset_text(read_file(path), path); }

ParamSet load_preset_text(const std::string& text, const std::string& path) {
  std::vector<std::string> chain;
  std::error_code ec;
  chain.push_back(fs::weakly_canonical(path, ec).string());
  ParamSet set = load_layer(text, path, chain);
  validate_preset(set);
  return set;
}

void validate_preset(const ParamSet& set) {
  check_log_grids(set);
  if (const SensorInfo* s = find_sensor(set.sensor_id())) s->validate(set);
}

void apply_settings(ParamSet& set, const std::vector<std::string>& assignments) {
  if (assignments.empty()) return;
  const ParamSchema& schema = schema_for(set.sensor_id(), set.origin());
  for (const auto& a : assignments) set.set_from_text(a, "--set", schema);
  validate_preset(set);
}

ParamSet load_preset(const std::string& id_or_path) { return load_preset_file(resolve_preset(id_or_path)); }

}  // namespace rangesim
