#include "core/preset.h"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <sstream>
#include <toml++/toml.h>

#include "core/user_error.h"

#ifndef RANGESIM_SOURCE_PRESET_DIR
#define RANGESIM_SOURCE_PRESET_DIR ""
#endif
#ifndef RANGESIM_INSTALL_PRESET_DIR
#define RANGESIM_INSTALL_PRESET_DIR ""
#endif

namespace fs = std::filesystem;

namespace rangesim {

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
    if (!fs::is_regular_file(id_or_path))
      throw UserError(fmt::format("{}: cannot read preset file (no such file)", id_or_path));
    return id_or_path;
  }
  for (const auto& dir : preset_search_path()) {
    const fs::path p = fs::path(dir) / (id_or_path + ".toml");
    if (fs::is_regular_file(p)) return p.string();
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

ParamValue read_value(const std::string& file, const std::string& key, const toml::node& entry,
                      const ParamSpec& spec) {
  const std::string where = where_of(file, entry);
  const toml::table* t = entry.as_table();
  if (!t || !t->contains("value") || !t->contains("source"))
    throw UserError(fmt::format("{}: {} must be an inline table {{ value = ..., source = \"...\" }} with value {}",
                                where, key, describe_range(spec)));
  for (const auto& [k, _] : *t)
    if (k != "value" && k != "source")
      throw UserError(fmt::format("{}: {} has unknown field '{}'; allowed: value, source", where, key, k.str()));
  ParamValue v;
  v.kind = spec.kind;
  const auto* source = (*t)["source"].as_string();
  if (!source || source->get().empty())
    throw UserError(fmt::format("{}: {}.source must be a non-empty string naming where the value comes from", where, key));
  v.source = source->get();
  const toml::node& value = *t->get("value");
  switch (spec.kind) {
    case ParamKind::Real:
      if (auto d = value.value_exact<double>()) v.number = *d;
      else if (auto i = value.value_exact<int64_t>()) v.number = static_cast<double>(*i);
      else throw UserError(fmt::format("{}: {} must be a number ({})", where, key, describe_range(spec)));
      break;
    case ParamKind::Integer:
      if (auto i = value.value_exact<int64_t>()) v.number = static_cast<double>(*i);
      else throw UserError(fmt::format("{}: {} must be an integer ({})", where, key, describe_range(spec)));
      break;
    case ParamKind::Boolean:
      if (auto b = value.value_exact<bool>()) v.number = *b ? 1.0 : 0.0;
      else throw UserError(fmt::format("{}: {} must be true or false", where, key));
      break;
    case ParamKind::Text:
      if (auto s = value.value_exact<std::string>()) v.text = *s;
      else throw UserError(fmt::format("{}: {} must be a string ({})", where, key, describe_range(spec)));
      if (!spec.choices.empty()) {
        bool ok = false;
        for (const auto& c : spec.choices) ok = ok || c == v.text;
        if (!ok) throw UserError(fmt::format("{}: {} = \"{}\" is not allowed; allowed: {}", where, key, v.text, describe_range(spec)));
      }
      break;
  }
  check_range(spec, v.number, where);
  return v;
}

}  // namespace

ParamSet load_preset_file(const std::string& path) {
  if (!fs::is_regular_file(path)) throw UserError(fmt::format("{}: cannot read preset file (not a regular file)", path));
  std::ifstream in(path, std::ios::binary);
  if (!in) throw UserError(fmt::format("{}: cannot read preset file", path));
  std::ostringstream text;
  text << in.rdbuf();
  if (in.bad()) throw UserError(fmt::format("{}: cannot read preset file", path));
  return load_preset_text(text.str(), path);
}

ParamSet load_preset_text(const std::string& text, const std::string& path) {
  toml::table root;
  try {
    root = toml::parse(text, path);
  } catch (const toml::parse_error& e) {
    throw UserError(fmt::format("{}:{}:{}: TOML syntax error: {}", path, e.source().begin.line,
                                e.source().begin.column, e.description()));
  }
  const auto* id = root["sensor"]["id"].as_string();
  if (!id && root["sensor"]["id"])
    throw UserError(fmt::format("{}: sensor.id must be a string; allowed: {}", where_of(path, *root["sensor"]["id"].node()),
                                sensor_ids()));
  if (!id) throw UserError(fmt::format("{}: missing key sensor.id; allowed: {}", path, sensor_ids()));
  const ParamSchema& schema = schema_for(id->get(), path);
  ParamSet set(path, id->get());

  for (const auto& [section_key, section_node] : root) {
    const std::string section = std::string(section_key.str());
    const toml::table* section_table = section_node.as_table();
    if (!section_table)
      throw UserError(fmt::format("{}: top-level key '{}' must be a [section]", where_of(path, section_node), section));
    for (const auto& [name_key, entry] : *section_table) {
      const std::string key = section + "." + std::string(name_key.str());
      if (key == "sensor.id") continue;
      const ParamSpec* spec = schema.find(key);
      if (!spec) {
        std::string allowed;
        if (section == "sensor") allowed = "sensor.id";
        for (const auto& p : schema.params)
          if (p.key.rfind(section + ".", 0) == 0) allowed += (allowed.empty() ? "" : ", ") + p.key;
        throw UserError(fmt::format("{}: unknown key '{}' for sensor {}; allowed in [{}]: {}", where_of(path, entry),
                                    key, id->get(), section, allowed.empty() ? "(no such section)" : allowed));
      }
      set.mutable_values()[key] = read_value(path, key, entry, *spec);
    }
  }
  for (const auto& spec : schema.params)
    if (!set.has(spec.key))
      throw UserError(fmt::format("{}: missing key '{}' ({}; {})", path, spec.key, spec.description, describe_range(spec)));
  return set;
}

ParamSet load_preset(const std::string& id_or_path) { return load_preset_file(resolve_preset(id_or_path)); }

}  // namespace rangesim
