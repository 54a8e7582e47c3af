// rangesim list / rangesim show: the presets and their resolved parameters.
#include <fmt/format.h>
#include <iterator>
#include <nlohmann/json.hpp>

#include "app/command_data.h"
#include "app/commands.h"
#include "core/preset.h"
#include "core/user_error.h"
#include "golden/common/evaluate_sensor.h"

namespace rangesim::app {

namespace {
std::vector<SensorCommand>& sensor_commands() {
  static std::vector<SensorCommand> list;
  return list;
}

const char* const kGoldenCommands[] = {"evaluate", "frame-rate", "table", "sweep"};

// The commands in the order `list` shows them: the golden ones, then the registered ones.
std::vector<std::string> command_names() {
  std::vector<std::string> names(std::begin(kGoldenCommands), std::end(kGoldenCommands));
  for (const auto& c : sensor_commands()) names.push_back(c.name);
  return names;
}
}  // namespace

void add_sensor_command(const SensorCommand& c) {
  for (auto& e : sensor_commands())
    if (e.name == c.name) return void(e = c);
  sensor_commands().push_back(c);
}

nlohmann::json list_json() {
  nlohmann::json list = nlohmann::json::array();
  for (const auto& s : sensors()) {
    const bool modelled = golden::golden_model(s.id) != nullptr;  // evaluate, table and frame-rate
    // Every command and whether it runs for this sensor: the golden ones (sweep varies the golden
    // evaluation) and those whose registries the program linked.
    nlohmann::json commands = nlohmann::json::object();
    for (const char* c : kGoldenCommands) commands[c] = modelled;
    for (const auto& c : sensor_commands()) commands[c.name] = c.runs(s.id);
    std::string file;
    try {
      file = resolve_preset(s.id);
    } catch (const UserError&) {
      file = "(preset file not found)";
    }
    list.push_back({{"id", s.id},
                    {"title", s.title},
                    {"thesis_ref", s.thesis_ref},
                    {"golden_modelled", modelled},
                    {"timing_modelled", modelled},
                    {"commands", commands},
                    {"file", file}});
  }
  return list;
}

int run_list(const ListOptions& opt) {
  const nlohmann::json list = list_json();
  if (opt.json) {
    fmt::print("{}\n", list.dump(2));
    return 0;
  }
  // One column per command.
  const std::vector<std::string> names = command_names();
  std::string head = fmt::format("{:<17} {:<7}", "preset", "thesis");
  for (const auto& n : names) head += fmt::format(" {:<{}}", n, n.size());
  fmt::print("{} architecture\n", head);
  for (const auto& s : list) {
    std::string line = fmt::format("{:<17} {:<7}", s["id"].get<std::string>(), s["thesis_ref"].get<std::string>());
    for (const auto& n : names) line += fmt::format(" {:<{}}", s["commands"][n].get<bool>() ? "yes" : "-", n.size());
    fmt::print("{} {}\n", line, s["title"].get<std::string>());
  }
  fmt::print("(\"-\": the command does not run for that sensor, exit 3)\n");
  return 0;
}

namespace {

std::string value_text(const ParamValue& v) {
  switch (v.kind) {
    case ParamKind::Text: return v.text;
    case ParamKind::Boolean: return v.number != 0 ? "true" : "false";
    case ParamKind::Integer: return fmt::format("{}", static_cast<long long>(v.number));
    case ParamKind::Real: return fmt::format("{:g}", v.number);
  }
  return "";
}

nlohmann::json value_json(const ParamValue& v) {
  switch (v.kind) {
    case ParamKind::Text: return v.text;
    case ParamKind::Boolean: return v.number != 0;
    case ParamKind::Integer: return static_cast<long long>(v.number);
    case ParamKind::Real: return v.number;
  }
  return nullptr;
}

}  // namespace

nlohmann::json show_json(const ParamSet& params) {
  const ParamSchema& schema = schema_for(params.sensor_id(), params.origin());
  nlohmann::json j;
  j["sensor"] = params.sensor_id();
  j["file"] = params.origin();
  j["golden_modelled"] = golden::golden_model(params.sensor_id()) != nullptr;
  nlohmann::json ps = nlohmann::json::object();
  for (const auto& spec : schema.params) {
    const ParamValue& v = params.at(spec.key);
    ps[spec.key] = {{"value", value_json(v)},
                    {"unit", spec.unit},
                    {"source", v.source},
                    {"file", v.file},
                    {"description", spec.description},
                    {"allowed", describe_range(spec)}};
  }
  j["parameters"] = ps;
  return j;
}

int run_show(const ShowOptions& opt) {
  ParamSet params = load_preset(opt.preset);
  apply_settings(params, opt.settings);
  const ParamSchema& schema = schema_for(params.sensor_id(), params.origin());
  const SensorInfo* info = find_sensor(params.sensor_id());
  if (opt.json) {
    fmt::print("{}\n", show_json(params).dump(2));
    return 0;
  }
  fmt::print("{} ({}) — {}\nfile: {}\n", params.sensor_id(), info ? info->thesis_ref : "?", info ? info->title : "",
             params.origin());
  std::string section;
  for (const auto& spec : schema.params) {
    const std::string sec = spec.key.substr(0, spec.key.find('.'));
    if (sec != section) {
      section = sec;
      fmt::print("\n[{}]\n", section);
    }
    const ParamValue& v = params.at(spec.key);
    fmt::print("  {:<32} {:>14} {:<3}  {}\n", spec.key.substr(spec.key.find('.') + 1), value_text(v), spec.unit,
               spec.description);
    // Where the value came from, when not the file shown at the top (a base preset, --set).
    const std::string from = v.file == params.origin() ? "" : fmt::format(" (from {})", v.file);
    fmt::print("  {:<32} {:>14} {:<3}  source: {}{}\n", "", "", "", v.source, from);
  }
  return 0;
}

}  // namespace rangesim::app
