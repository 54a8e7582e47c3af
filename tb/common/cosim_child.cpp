#include "tb/common/cosim_child.h"

#include <cstdio>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "core/preset.h"
#include "core/user_error.h"

namespace rangesim::tb {
namespace {

using nlohmann::json;

struct ChildArgs {
  std::string preset, report;
  std::vector<std::string> settings;  // --set KEY=VALUE after the preset
  CosimOptions options;
};

ChildArgs parse_args(int argc, char** argv) {
  ChildArgs a;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string k = argv[i], v = argv[i + 1];
    if (k == "--preset")
      a.preset = v;
    else if (k == "--report")
      a.report = v;
    else if (k == "--cycles")
      a.options.cycles = std::stoull(v);
    else if (k == "--seed")
      a.options.seed = std::stoull(v);
    else if (k == "--fault")
      a.options.inject_fault = v;
    else if (k == "--trace")
      a.options.trace_path = v;
    else if (k == "--set")
      a.settings.push_back(v);
    else
      throw std::invalid_argument("cosim child: unknown argument " + k);
  }
  if (a.preset.empty() || a.report.empty())
    throw std::invalid_argument("cosim child: --preset and --report are required");
  return a;
}

// Written next to the destination, then renamed: the parent never reads half a report.
void write_file(const std::string& path, const std::string& text) {
  const std::string tmp = path + ".part";
  {
    std::ofstream out(tmp, std::ios::binary);
    out << text;
    if (!out) throw std::runtime_error("cosim child: cannot write " + tmp);
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) throw std::runtime_error("cosim child: cannot rename " + tmp);
}

}  // namespace

std::string cosim_report_file_text(const CosimReport& r, const RtlCoverage& cov) {
  json checks = json::object();
  for (const auto& [name, c] : r.checks) checks[name] = {c.transactions, c.mismatches};
  json ms = json::array();
  for (const auto& m : r.first_mismatches)
    ms.push_back({{"check", m.check},
                  {"frame", m.frame},
                  {"row", m.row},
                  {"column", m.column},
                  {"cycle", m.cycle},
                  {"expected", m.expected},
                  {"actual", m.actual}});
  const json rep{{"target", r.target},
                 {"cycles", r.cycles},
                 {"transactions", r.transactions},
                 {"mismatches", r.mismatches},
                 {"first_mismatches", ms},
                 {"golden_checks", r.golden_checks},
                 {"rtl_assertions_failed", r.rtl_assertions_failed},
                 {"sc_errors", r.sc_errors},
                 {"fault_injected", r.fault_injected},
                 {"fault_site", r.fault_site},
                 {"checks", checks}};
  const json c{{"available", cov.available},
               {"line_points", cov.line_points},
               {"line_hit", cov.line_hit},
               {"toggle_points", cov.toggle_points},
               {"toggle_hit", cov.toggle_hit},
               {"uncovered_lines", cov.uncovered_lines},
               {"data", cov.data}};
  return json{{"report", rep}, {"coverage", c}}.dump();
}

std::string cosim_error_file_text(const std::string& message, bool user_error) {
  return json{{"error", message}, {"user_error", user_error}}.dump();
}

void parse_cosim_report_file(const std::string& text, CosimReport& r, RtlCoverage& cov) {
  const json j = json::parse(text);
  if (j.contains("error")) {
    const std::string msg = j["error"].get<std::string>();
    if (j.value("user_error", false)) throw UserError(msg);
    throw std::runtime_error(msg);
  }
  const json& p = j.at("report");
  r.target = p.at("target").get<std::string>();
  r.cycles = p.at("cycles").get<std::uint64_t>();
  r.transactions = p.at("transactions").get<std::uint64_t>();
  r.mismatches = p.at("mismatches").get<std::uint64_t>();
  for (const auto& m : p.at("first_mismatches"))
    r.first_mismatches.push_back({m.at("check").get<std::string>(), m.at("frame").get<long long>(),
                                  m.at("row").get<long long>(), m.at("column").get<long long>(),
                                  m.at("cycle").get<std::uint64_t>(), m.at("expected").get<std::string>(),
                                  m.at("actual").get<std::string>()});
  r.golden_checks = p.at("golden_checks").get<std::uint64_t>();
  r.rtl_assertions_failed = p.at("rtl_assertions_failed").get<int>();
  r.sc_errors = p.at("sc_errors").get<int>();
  r.fault_injected = p.at("fault_injected").get<bool>();
  r.fault_site = p.at("fault_site").get<std::string>();
  for (const auto& [name, c] : p.at("checks").items())
    r.checks[name] = {c.at(0).get<std::uint64_t>(), c.at(1).get<std::uint64_t>()};
  const json& c = j.at("coverage");
  cov.available = c.at("available").get<bool>();
  cov.line_points = c.at("line_points").get<long long>();
  cov.line_hit = c.at("line_hit").get<long long>();
  cov.toggle_points = c.at("toggle_points").get<long long>();
  cov.toggle_hit = c.at("toggle_hit").get<long long>();
  cov.uncovered_lines = c.at("uncovered_lines").get<std::map<std::string, std::set<int>>>();
  cov.data = c.at("data").get<std::string>();
}

int run_cosim_child(int argc, char** argv, PresetCosimRunner runner) {
  ChildArgs a;
  try {
    a = parse_args(argc, argv);
  } catch (const std::exception& e) {
    std::cerr << e.what() << "\n";
    return 1;
  }
  try {
    ParamSet preset = load_preset_file(a.preset);
    apply_settings(preset, a.settings);
    const CosimReport r = runner(preset, a.options);
    write_file(a.report, cosim_report_file_text(r, rtl_coverage()));
    return 0;
  } catch (const UserError& e) {
    write_file(a.report, cosim_error_file_text(e.what(), true));
    return 2;
  } catch (const std::exception& e) {
    write_file(a.report, cosim_error_file_text(e.what(), false));
    return 1;
  }
}

}  // namespace rangesim::tb
