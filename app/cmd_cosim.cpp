// `rangesim cosim`: runs the co-simulation targets of tb/common/cosim_targets.cpp and reports what their
// scoreboards compared, the mismatches with their context and the RTL coverage.
//
// SystemC elaborates once per process, so `cosim all` runs each target in a child process (this
// binary again, `cosim <target> --json`) and gathers the JSON; a single target runs in-process.
// A preset (`cosim <preset.toml>`, or the id of a preset that is not a target name) runs the
// sensor's readout verilated at run time with the preset's parameters, in a child process built
// and cached by tb/common/rtl_build.h; its report comes back as JSON and renders the same way.
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <fstream>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "app/cli_common.h"
#include "app/commands.h"
#include "app/output_dir.h"
#include "app/output_lock.h"
#include "app/run_control.h"
#include "app/sweep_journal.h"
#include "core/preset.h"
#include "core/user_error.h"
#include "tb/common/cosim_coverage.h"
#include "tb/common/cosim_target.h"
#include "tb/common/rtl_build.h"
#include "tb/common/rtl_process.h"

namespace rangesim::app {
namespace {

using nlohmann::json;

constexpr unsigned long long kDefaultCycles = 100000, kMaxCycles = 1000000000ULL;
constexpr unsigned long long kAllFullCycles = 1000;  // ls-conventional-full in `all`: ten frame accesses

std::string target_names() {
  std::string s;
  for (const auto& t : tb::cosim_targets()) s += (s.empty() ? "" : ", ") + std::string(t.name);
  return s + ", all, or a preset file (.toml) of " + [] {
    std::string p;
    for (const auto& c : tb::preset_cosims()) p += (p.empty() ? "" : ", ") + std::string(c.sensor);
    return p;
  }();
}

const tb::CosimTarget* find_target(const std::string& name) {
  for (const auto& t : tb::cosim_targets())
    if (name == t.name) return &t;
  return nullptr;
}

// Directory and file name of a user-given output file, for OutputDir staging.
std::pair<std::string, std::string> split_path(const std::string& path) {
  const std::size_t slash = path.rfind('/');
  if (slash == std::string::npos) return {".", path};
  return {slash == 0 ? "/" : path.substr(0, slash), path.substr(slash + 1)};
}

json coverage_json(const tb::RtlCoverage& c) {
  json j;
  j["available"] = c.available;
  j["line_points"] = c.line_points;
  j["line_hit"] = c.line_hit;
  j["toggle_points"] = c.toggle_points;
  j["toggle_hit"] = c.toggle_hit;
  j["uncovered_lines"] = c.uncovered_lines;  // {"rtl/<folder>/<file>.sv": [line, ...]}
  return j;
}

json percent_or_null(long long hit, long long points) {
  return points > 0 ? json(100.0 * static_cast<double>(hit) / static_cast<double>(points)) : json(nullptr);
}

json report_json(const tb::CosimReport& r, const tb::RtlCoverage& cov, const std::string& fault, double wall_s) {
  json j;
  j["target"] = r.target;
  j["cycles"] = r.cycles;
  j["transactions"] = r.transactions;
  j["mismatches"] = r.mismatches;
  j["golden_checks"] = r.golden_checks;
  j["rtl_assertions_failed"] = r.rtl_assertions_failed;
  j["sc_errors"] = r.sc_errors;
  j["coverage_line"] = percent_or_null(cov.line_hit, cov.line_points);
  j["coverage_toggle"] = percent_or_null(cov.toggle_hit, cov.toggle_points);
  j["coverage"] = coverage_json(cov);
  j["fault"] =
      fault.empty() ? json(nullptr) : json{{"name", fault}, {"injected", r.fault_injected}, {"site", r.fault_site}};
  json ms = json::array();
  for (const auto& m : r.first_mismatches)
    ms.push_back({{"check", m.check},
                  {"frame", m.frame},
                  {"row", m.row},
                  {"column", m.column},
                  {"cycle", m.cycle},
                  {"expected", m.expected},
                  {"actual", m.actual}});
  j["first_mismatches"] = ms;
  json checks = json::object();
  for (const auto& [name, c] : r.checks)
    checks[name] = {{"transactions", c.transactions}, {"mismatches", c.mismatches}};
  j["checks"] = checks;
  j["wall_time_s"] = wall_s;
  return j;
}

// A run passes when nothing mismatched and, with a fault requested, the fault went in.
bool passed(const json& r) {
  if (r.value("mismatches", 1ULL) != 0) return false;
  return r["fault"].is_null();
}

std::string mismatch_line(const json& m) {
  // Harnesses that report a whole sentence (address_search) leave `expected` empty.
  if (m["expected"].get<std::string>().empty())
    return fmt::format("[{}] {}", m["check"].get<std::string>(), m["actual"].get<std::string>());
  std::string where;
  auto part = [&](const char* key, const char* label) {
    if (m[key].get<long long>() >= 0) where += fmt::format("{} {} ", label, m[key].get<long long>());
  };
  part("frame", "frame");
  part("row", "row");
  part("column", "column");
  where += fmt::format("cycle {}", m["cycle"].get<unsigned long long>());
  return fmt::format("[{}] {}: expected {}, actual {}", m["check"].get<std::string>(), where,
                     m["expected"].get<std::string>(), m["actual"].get<std::string>());
}

void print_text(const json& r) {
  auto pct = [](const json& v) {
    return v.is_null() ? std::string("n/a (uninstrumented)") : fmt::format("{:.1f} %", v.get<double>());
  };
  fmt::print("cosim {}: {}\n", r["target"].get<std::string>(), passed(r) ? "PASS" : "FAIL");
  fmt::print("  cycles compared      {}\n", r["cycles"].get<unsigned long long>());
  fmt::print("  transactions matched {} of {}\n",
             r["transactions"].get<unsigned long long>() -
                 std::min(r["transactions"].get<unsigned long long>(), r["mismatches"].get<unsigned long long>()),
             r["transactions"].get<unsigned long long>());
  fmt::print("  golden checks        {}\n", r["golden_checks"].get<unsigned long long>());
  fmt::print("  mismatches           {}\n", r["mismatches"].get<unsigned long long>());
  fmt::print("  RTL assertions fired {}\n", r["rtl_assertions_failed"].get<int>());
  fmt::print("  coverage line        {}\n", pct(r["coverage_line"]));
  fmt::print("  coverage toggle      {}\n", pct(r["coverage_toggle"]));
  for (const auto& [file, lines] : r["coverage"]["uncovered_lines"].items()) {
    std::string list;
    for (const auto& l : lines) list += (list.empty() ? "" : ", ") + std::to_string(l.get<int>());
    fmt::print("  uncovered lines      {}: {}\n", file, list);
  }
  if (!r["fault"].is_null())
    fmt::print("  injected fault       {}: {}\n", r["fault"]["name"].get<std::string>(),
               r["fault"]["injected"].get<bool>() ? r["fault"]["site"].get<std::string>()
                                                  : std::string("NOT applied (run longer)"));
  for (const auto& m : r["first_mismatches"]) fmt::print("    {}\n", mismatch_line(m));
  fmt::print("  wall time            {:.2f} s\n", r["wall_time_s"].get<double>());
}

std::string xml_escape(const std::string& s) {
  std::string o;
  for (char c : s) {
    switch (c) {
      case '&': o += "&amp;"; break;
      case '<': o += "&lt;"; break;
      case '>': o += "&gt;"; break;
      case '"': o += "&quot;"; break;
      default:
        if (static_cast<unsigned char>(c) >= 0x20 || c == '\n' || c == '\t') o += c;
    }
  }
  return o;
}

// One JUnit testcase: passes, or fails with `failures` (readable lines) as its text.
struct JunitCase {
  std::string classname, name;
  double time_s = 0;
  std::uint64_t failures = 0;
  std::string text, out;
};

// The testcases of one run: one per check its scoreboard compared (classname the target), and
// one "run" for what no check owns (a fault not applied, a stall); a run whose harness names no
// checks is one testcase.
std::vector<JunitCase> junit_cases(const json& r) {
  const std::string target = r["target"].get<std::string>();
  const double time_s = r["wall_time_s"].get<double>();
  const std::string out =
      fmt::format("cycles {} transactions {} mismatches {} golden_checks {}", r["cycles"].get<unsigned long long>(),
                  r["transactions"].get<unsigned long long>(), r["mismatches"].get<unsigned long long>(),
                  r["golden_checks"].get<unsigned long long>());
  std::string fault_line;
  if (!r["fault"].is_null())
    fault_line =
        "injected fault " + r["fault"]["name"].get<std::string>() + ": " + r["fault"]["site"].get<std::string>() + "\n";
  const json checks = r.value("checks", json::object());
  if (checks.empty()) {
    std::string body;
    for (const auto& m : r["first_mismatches"]) body += mismatch_line(m) + "\n";
    return {{"rangesim.cosim", target, time_s, passed(r) ? 0 : r["mismatches"].get<std::uint64_t>(), body + fault_line,
             out}};
  }
  std::vector<JunitCase> cases;
  std::uint64_t owned = 0;
  for (const auto& [name, c] : checks.items()) {
    JunitCase k{"rangesim.cosim." + target,
                name,
                0,
                c["mismatches"].get<std::uint64_t>(),
                "",
                fmt::format("transactions {} mismatches {}", c["transactions"].get<unsigned long long>(),
                            c["mismatches"].get<unsigned long long>())};
    for (const auto& m : r["first_mismatches"])
      if (m["check"] == name) k.text += mismatch_line(m) + "\n";
    if (k.failures && !fault_line.empty()) k.text += fault_line;
    owned += k.failures;
    cases.push_back(std::move(k));
  }
  const std::uint64_t rest =
      r["mismatches"].get<std::uint64_t>() - std::min(owned, r["mismatches"].get<std::uint64_t>());
  if (rest > 0 || (!r["fault"].is_null() && owned == 0)) {
    JunitCase run{"rangesim.cosim." + target, "run", 0, std::max<std::uint64_t>(rest, 1), fault_line, out};
    for (const auto& m : r["first_mismatches"])
      if (!checks.contains(m["check"].get<std::string>())) run.text += mismatch_line(m) + "\n";
    cases.push_back(std::move(run));
  }
  cases.front().time_s = time_s;  // the run's wall time, once
  cases.front().out = out + "; " + cases.front().out;
  return cases;
}

std::string junit_xml(const std::vector<json>& runs) {
  std::vector<JunitCase> cases;
  double total = 0;
  for (const auto& r : runs) {
    for (auto& c : junit_cases(r)) cases.push_back(std::move(c));
    total += r["wall_time_s"].get<double>();
  }
  int failures = 0;
  for (const auto& c : cases) failures += c.failures > 0;
  std::string x = "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n";
  x += fmt::format("<testsuites name=\"rangesim cosim\" tests=\"{}\" failures=\"{}\" time=\"{:.3f}\">\n", cases.size(),
                   failures, total);
  x += fmt::format("  <testsuite name=\"rangesim.cosim\" tests=\"{}\" failures=\"{}\" errors=\"0\" time=\"{:.3f}\">\n",
                   cases.size(), failures, total);
  for (const auto& c : cases) {
    x += fmt::format("    <testcase classname=\"{}\" name=\"{}\" time=\"{:.3f}\">\n", xml_escape(c.classname),
                     xml_escape(c.name), c.time_s);
    if (c.failures)
      x += fmt::format("      <failure message=\"{} mismatches\" type=\"mismatch\">{}</failure>\n", c.failures,
                       xml_escape(c.text));
    x += fmt::format("      <system-out>{}</system-out>\n", xml_escape(c.out));
    x += "    </testcase>\n";
  }
  x += "  </testsuite>\n</testsuites>\n";
  return x;
}

// What makes the results of `all` what they are: a journal from other options is refused.
std::string all_fingerprint(const CosimCommandOptions& o, unsigned long long cycles,
                            const std::vector<tb::CosimTarget>& targets) {
  std::string f = fmt::format("rangesim cosim all\ncycles {}\nseed {}\ntrace {}\ntargets", cycles, o.seed, o.trace);
  for (const auto& t : targets) f += std::string(" ") + t.name;
  return f + "\n";
}

std::string resume_command(const CosimCommandOptions& o) {
  std::string c = fmt::format("rangesim cosim all --seed {}", o.seed);
  if (o.cycles) c += fmt::format(" --cycles {}", *o.cycles);
  if (!o.trace.empty()) c += " --trace " + shell_quote(o.trace);
  if (!o.junit.empty()) c += " --junit " + shell_quote(o.junit);
  if (o.json) c += " --json";
  return c + " --journal " + shell_quote(o.journal) + " --resume";
}

// Runs `rangesim cosim <target> --json ...` as a child process and parses its JSON.
// UserError unless `fault` is "" or one of the target's faults.
void check_fault(const std::string& fault, const tb::CosimTarget& target, const std::string& what) {
  if (fault.empty()) return;
  std::string names;
  for (const auto& f : target.faults) {
    if (f == fault) return;
    names += (names.empty() ? "" : ", ") + f;
  }
  throw UserError("cosim: --inject-fault '" + fault + "' is not a fault of " + what +
                  "; allowed: " + (names.empty() ? std::string("none") : names));
}

// A fault that never went in proves nothing: it counts as a mismatch.
void require_fault_applied(tb::CosimReport& r, const std::string& fault) {
  if (fault.empty() || r.fault_injected) return;
  ++r.mismatches;
  r.first_mismatches.push_back({"fault", -1, -1, -1, r.cycles, fault + " applied", "not applied (run longer)"});
}

// The preset file `name` stands for: a .toml file, or a preset id that is not a target.
std::string preset_path_of(const std::string& name) {
  if (name.find('/') != std::string::npos || name.find(".toml") != std::string::npos) return resolve_preset(name);
  try {
    return resolve_preset(name);
  } catch (const UserError&) {
    throw UserError("cosim: unknown target '" + name + "'; allowed: " + target_names());
  }
}

// `cosim <preset>`: the sensor's readout verilated with the preset's Verilog parameters (cached),
// run in a child process on the same options as a built-in target.
// With --rtl: the user's files, absolute; UserError naming a file that cannot be read.
std::vector<std::string> user_rtl_files(const CosimCommandOptions& opt) {
  std::vector<std::string> files;
  for (const auto& f : opt.rtl) {
    std::error_code ec;
    if (!std::filesystem::is_regular_file(f, ec) || access(f.c_str(), R_OK) != 0)
      throw UserError("cosim: --rtl '" + f +
                      "': " + (std::filesystem::exists(f, ec) ? "not a readable file" : "no such file"));
    files.push_back(std::filesystem::absolute(f).lexically_normal().string());
  }
  return files;
}

std::string file_names(const std::vector<std::string>& files) {
  std::string s;
  for (const auto& f : files) s += (s.empty() ? "" : "+") + std::filesystem::path(f).filename().string();
  return s;
}

json run_preset(const CosimCommandOptions& opt, const std::string& path, unsigned long long cycles,
                const std::string& trace_file, tb::RtlCoverage& cov) {
  ParamSet preset = load_preset_file(path);
  apply_settings(preset, opt.settings);
  const tb::PresetCosim* pc = nullptr;
  for (const auto& c : tb::preset_cosims())
    if (c.sensor == preset.sensor_id()) pc = &c;
  if (!pc) {
    std::string ids;
    for (const auto& c : tb::preset_cosims()) ids += (ids.empty() ? "" : ", ") + std::string(c.sensor);
    throw UserError(
        fmt::format("{}: sensor.id = {}: no RTL co-simulation at a preset's own parameters; allowed: {} "
                    "(or the built-in target: rangesim cosim {})",
                    path, preset.sensor_id(), ids, preset.sensor_id()));
  }
  const tb::CosimTarget* target = find_target(pc->target);
  check_fault(opt.inject_fault, *target, path + " (the faults of " + pc->target + ")");
  tb::RtlBuildSpec spec = pc->spec(preset);
  spec.user_files = user_rtl_files(opt);
  if (!spec.user_files.empty()) {
    const std::vector<std::string> blocks = tb::check_user_rtl(spec, preset, opt.top);
    if (!opt.json)
      fmt::print(stderr, "cosim: {} replace{} {} in {} (ports as in docs/rtl-contract.md)\n",
                 file_names(spec.user_files), spec.user_files.size() == 1 ? "s" : "", fmt::join(blocks, ", "),
                 spec.top);
  }
  const std::string exe = tb::rtl_cosim_executable(spec);
  if (!opt.json) fmt::print(stderr, "cosim: {} ({} cycles, seed {})...\n", path, cycles, opt.seed);
  tb::CosimOptions o;
  o.cycles = cycles;
  o.seed = opt.seed;
  o.inject_fault = opt.inject_fault;
  o.trace_path = trace_file;
  const auto t0 = std::chrono::steady_clock::now();
  tb::CosimReport r;
  tb::run_rtl_cosim(exe, path, opt.settings, o, r, cov);
  if (!spec.user_files.empty()) r.target += "+rtl:" + file_names(spec.user_files);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  require_fault_applied(r, opt.inject_fault);
  return report_json(r, cov, opt.inject_fault, wall);
}

json run_child(const std::string& target, const CosimCommandOptions& opt, unsigned long long cycles,
               const std::string& trace, const std::string& coverage_out) {
  std::vector<std::string> args{
      "rangesim", "cosim", target, "--json", "--cycles", std::to_string(cycles), "--seed", std::to_string(opt.seed)};
  if (!trace.empty()) args.insert(args.end(), {"--trace", trace});
  if (!coverage_out.empty()) args.insert(args.end(), {"--coverage-out", coverage_out});
  // The child gets what is left of the time budget (it ends itself, exit 4) and the memory budget.
  if (std::isfinite(time_budget_left()))
    args.insert(args.end(), {"--max-seconds", fmt::format("{:.3f}", std::max(0.001, time_budget_left()))});
  if (!run_budget().max_memory_text.empty()) args.insert(args.end(), {"--max-memory", run_budget().max_memory_text});
  int fds[2];
  if (pipe(fds) != 0) throw std::runtime_error("cosim all: pipe failed");
  const pid_t parent = getpid();
  const pid_t pid = fork();
  if (pid < 0) throw std::runtime_error("cosim all: fork failed");
  if (pid == 0) {
    tb::die_with_parent(parent);
    dup2(fds[1], STDOUT_FILENO);
    close(fds[0]);
    close(fds[1]);
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    execv("/proc/self/exe", argv.data());
    _exit(127);
  }
  close(fds[1]);
  std::string out;
  char buf[4096];
  for (ssize_t n; (n = read(fds[0], buf, sizeof buf)) > 0;) out.append(buf, static_cast<std::size_t>(n));
  close(fds[0]);
  int status = 0;
  waitpid(pid, &status, 0);
  // The JSON is the last line that parses (Verilator's $error messages may precede it).
  const std::size_t start = out.find("\n{");
  const std::string text = out.rfind('{', 0) == 0 ? out : (start == std::string::npos ? "" : out.substr(start + 1));
  json j = json::parse(text, nullptr, false);
  if (j.is_discarded() || !j.is_object())
    throw std::runtime_error("cosim all: target " + target + " exited with status " +
                             std::to_string(WEXITSTATUS(status)) + " without a report");
  return j;
}

}  // namespace

bool has_preset_cosim(const std::string& target) { return tb::preset_cosim_of_target(target) != nullptr; }

std::string preset_cosim_targets() {
  std::string s;
  for (const auto& c : tb::preset_cosims()) s += (s.empty() ? "" : ", ") + std::string(c.target);
  return s;
}

std::string instance_preset_of(const std::string& target) {
  return tb::instance_preset_path(*tb::preset_cosim_of_target(target));
}

// `all` writes one file per target: FILE_<target><ext> ("" stays "").
std::string per_target(const std::string& path, const std::string& ext, const std::string& target) {
  if (path.empty()) return "";
  std::string stem = path;
  if (stem.size() > ext.size() && stem.compare(stem.size() - ext.size(), ext.size(), ext) == 0)
    stem.resize(stem.size() - ext.size());
  return stem + "_" + target + ext;
}

// The output files of one run (--junit, --trace, --coverage-out), staged next to their
// destination and committed together: one OutputDir per directory (a second one there would
// share, and on commit remove, the first one's staging).
class StagedFiles {
 public:
  // The staged path of `path` ("" stays ""); UserError when it names a directory.
  std::string stage(const std::string& path, const std::string& flag) {
    if (path.empty()) return "";
    auto [d, n] = split_path(path);
    if (n.empty()) throw UserError("cosim: " + flag + " '" + path + "' names a directory; give a file");
    auto& dir = dirs_[d];
    if (!dir) dir = std::make_unique<OutputDir>(d, flag, OutputFolder{"", false, true, true});
    const std::string staged = dir->staged(n);
    of_staged_[staged] = dir.get();
    return staged;
  }
  // Files the run wrote beside staged file `staged` (a trace's save file and filters:
  // <stem>.gtkw, <stem>.*.txt) are committed with it. They name each other, so they are staged
  // under their own names (OutputFolder::same_names).
  void adopt_companions(const std::string& staged) {
    if (staged.empty()) return;
    const std::filesystem::path p(staged);
    const std::string prefix = p.stem().string() + ".";
    std::error_code ec;
    for (const auto& e : std::filesystem::directory_iterator(p.parent_path(), ec)) {
      const std::string name = e.path().filename().string();
      if (name != p.filename().string() && name.rfind(prefix, 0) == 0) of_staged_.at(staged)->staged(name);
    }
  }
  void commit() {
    for (auto& [d, o] : dirs_) o->commit();
  }

 private:
  std::map<std::string, std::unique_ptr<OutputDir>> dirs_;
  std::map<std::string, OutputDir*> of_staged_;  // staged path -> its folder
};

void write_text(const std::string& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  if (!out) throw std::runtime_error("cosim: cannot write " + path);
}

bool cosim_runs(const std::string& sensor) {
  for (const auto& t : tb::cosim_targets())
    if (sensor == t.name) return true;
  return false;
}

int run_cosim(const CosimCommandOptions& opt) {
  const auto& targets = tb::cosim_targets();
  if (opt.list) {
    if (opt.json) {
      json j = json::array();
      for (const auto& t : targets)
        j.push_back({{"name", t.name}, {"description", t.description}, {"faults", t.faults}});
      std::cout << j.dump(2) << "\n";
    } else {
      for (const auto& t : targets) {
        std::string faults;
        for (const auto& f : t.faults) faults += (faults.empty() ? "" : ", ") + f;
        fmt::print("{:<26} {}\n{:<26} faults: {}\n", t.name, t.description, "", faults.empty() ? "none" : faults);
      }
    }
    return kExitOk;
  }
  if (opt.target.empty()) throw UserError("cosim: name a target (" + target_names() + ") or use --list");
  const bool all = opt.target == "all";
  const tb::CosimTarget* target = all ? nullptr : find_target(opt.target);
  const std::string preset_path = all || target ? std::string() : preset_path_of(opt.target);
  if (!opt.settings.empty() && preset_path.empty())
    throw UserError(
        fmt::format("--set: {} is a built-in target with fixed parameters; --set applies to a preset "
                    "file (rangesim cosim presets/<sensor>.toml --set KEY=VALUE)",
                    opt.target));
  const unsigned long long cycles = opt.cycles.value_or(kDefaultCycles);
  if (cycles < 1 || cycles > kMaxCycles)
    throw UserError(fmt::format("cosim: --cycles {} out of range; allowed 1..{}", cycles, kMaxCycles));
  if (opt.resume && !all)
    throw UserError("cosim: --resume continues an interrupted 'all' run; a single target has no journal");
  if (all && !opt.inject_fault.empty())
    throw UserError("cosim: --inject-fault needs one target (fault names are per target; see --list)");
  if (target) check_fault(opt.inject_fault, *target, opt.target);
  if (!opt.rtl.empty() && (all || (target && !has_preset_cosim(opt.target))))
    throw UserError(
        fmt::format("cosim: --rtl replaces blocks inside a sensor's readout; allowed targets: {} or a "
                    "preset file of one of them",
                    preset_cosim_targets()));
  if (!opt.top.empty() && opt.rtl.empty())
    throw UserError("cosim: --top names the block of your --rtl files; add --rtl");
  if (!opt.junit.empty()) check_output_file(opt.junit, "--junit");
  if (!opt.trace.empty() && !all) check_output_file(opt.trace, "--trace");
  if (!opt.coverage_out.empty() && !all) check_output_file(opt.coverage_out, "--coverage-out");
  // Output files are staged next to their destination and appear only when complete.
  StagedFiles staged;
  const std::string junit_file = staged.stage(opt.junit, "--junit");
  const std::string trace_file = all ? "" : staged.stage(opt.trace, "--trace");
  const std::string coverage_file = all ? "" : staged.stage(opt.coverage_out, "--coverage-out");

  std::vector<json> runs;
  std::unique_ptr<SweepJournal> journal;
  std::unique_ptr<OutputLock> journal_lock;
  if (all) {
    // One run per journal: a second `all` (or a --resume) on a live run's journal is refused.
    const std::filesystem::path journal_dir = std::filesystem::absolute(opt.journal).parent_path();
    std::error_code ec;
    std::filesystem::create_directories(journal_dir, ec);
    journal_lock = std::make_unique<OutputLock>(journal_dir.string(), "--journal");
    journal = std::make_unique<SweepJournal>(opt.journal, all_fingerprint(opt, cycles, targets), opt.resume);
    if (!journal->done().empty())
      fmt::print(stderr, "cosim: resuming: {} of {} targets from {}\n", journal->done().size(), targets.size(),
                 journal->path());
    SigintGuard sigint;  // children die of Ctrl-C themselves; the parent stops after them
    for (std::size_t i = 0; i < targets.size(); ++i) {
      const auto& t = targets[i];
      const auto it = journal->done().find(static_cast<long long>(i));
      if (it != journal->done().end()) {
        runs.push_back(json::parse(it->second));
        continue;
      }
      if (time_budget_left() <= 0) {
        fmt::print(stderr, "cosim: --max-seconds {} exceeded; {} of {} targets kept in {}; continue with:\n  {}\n",
                   run_budget().max_seconds_text, runs.size(), targets.size(), journal->path(), resume_command(opt));
        return kExitBudget;
      }
      const std::string trace = per_target(opt.trace, ".vcd", t.name);
      // The full-size readout costs milliseconds of wall time per cycle (375 x 365 pixels): in
      // `all` it gets at most ten frame accesses, else a large N would run for hours. Run it
      // alone for more.
      const bool full = std::string(t.name) == "ls-conventional-full";
      const unsigned long long n = full ? std::min(cycles, kAllFullCycles) : cycles;
      fmt::print(stderr, "cosim: {} ({} cycles{})...\n", t.name, n, n < cycles ? ", capped in 'all'" : "");
      json r;
      try {
        r = run_child(t.name, opt, n, trace, per_target(opt.coverage_out, ".dat", t.name));
      } catch (const std::runtime_error&) {
        if (!sigint_flag().load() && time_budget_left() > 0) throw;
      }
      if (sigint_flag().load() || time_budget_left() <= 0) {
        const bool budget = !sigint_flag().load();
        fmt::print(stderr, "cosim: {}; {} of {} targets kept in {}; continue with:\n  {}\n",
                   budget ? fmt::format("--max-seconds {} exceeded", run_budget().max_seconds_text) : stop_reason(),
                   runs.size(), targets.size(), journal->path(), resume_command(opt));
        return budget ? kExitBudget : stop_exit_code();
      }
      journal->append(static_cast<long long>(i), r.dump());
      runs.push_back(std::move(r));
      fmt::print(stderr, "cosim: {} done: {} mismatches\n", t.name,
                 runs.back()["mismatches"].get<unsigned long long>());
    }
  } else if (!preset_path.empty() || !opt.rtl.empty()) {
    tb::RtlCoverage cov;
    runs.push_back(
        run_preset(opt, preset_path.empty() ? instance_preset_of(opt.target) : preset_path, cycles, trace_file, cov));
    if (!coverage_file.empty()) write_text(coverage_file, cov.data);
  } else {
    if (!opt.json) fmt::print(stderr, "cosim: {} ({} cycles, seed {})...\n", target->name, cycles, opt.seed);
    tb::CosimOptions o;
    o.cycles = cycles;
    o.seed = opt.seed;
    o.inject_fault = opt.inject_fault;
    o.trace_path = trace_file;
    // SystemC's and Verilator's own messages ($error of a firing assertion, "simulation stopped")
    // go to stdout; during the run stdout is sent to stderr so that --json output stays JSON.
    std::fflush(stdout);
    const int saved_stdout = dup(STDOUT_FILENO);
    dup2(STDERR_FILENO, STDOUT_FILENO);
    const auto t0 = std::chrono::steady_clock::now();
    tb::CosimReport r;
    try {
      r = target->run(o);
    } catch (...) {
      std::fflush(stdout);
      dup2(saved_stdout, STDOUT_FILENO);
      close(saved_stdout);
      throw;
    }
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::fflush(stdout);
    dup2(saved_stdout, STDOUT_FILENO);
    close(saved_stdout);
    require_fault_applied(r, opt.inject_fault);
    const tb::RtlCoverage cov = tb::rtl_coverage();
    runs.push_back(report_json(r, cov, opt.inject_fault, wall));
    if (!coverage_file.empty()) write_text(coverage_file, cov.data);
  }

  json out;
  if (all) {
    unsigned long long c = 0, t = 0, m = 0;
    long long lp = 0, lh = 0, tp = 0, th = 0;
    for (const auto& r : runs) {
      c += r["cycles"].get<unsigned long long>();
      t += r["transactions"].get<unsigned long long>();
      m += r["mismatches"].get<unsigned long long>();
      lp += r["coverage"]["line_points"].get<long long>();
      lh += r["coverage"]["line_hit"].get<long long>();
      tp += r["coverage"]["toggle_points"].get<long long>();
      th += r["coverage"]["toggle_hit"].get<long long>();
    }
    out = {{"target", "all"},
           {"cycles", c},
           {"transactions", t},
           {"mismatches", m},
           {"coverage_line", percent_or_null(lh, lp)},
           {"coverage_toggle", percent_or_null(th, tp)},
           {"targets", runs}};
  } else {
    out = runs.front();
  }
  if (!junit_file.empty()) write_text(junit_file, junit_xml(runs));
  staged.adopt_companions(trace_file);
  staged.commit();
  if (journal) {  // the run is complete: nothing left to resume
    journal->remove();
    std::error_code ec;  // the default folder goes too when nothing else is in it
    if (opt.journal == CosimCommandOptions{}.journal)
      std::filesystem::remove(std::filesystem::path(journal->path()).parent_path(), ec);
  }

  if (opt.json) {
    std::cout << out.dump(2) << "\n";
  } else {
    for (const auto& r : runs) print_text(r);
    if (all)
      fmt::print("all: {} targets, {} cycles, {} transactions, {} mismatches\n", runs.size(),
                 out["cycles"].get<unsigned long long>(), out["transactions"].get<unsigned long long>(),
                 out["mismatches"].get<unsigned long long>());
  }
  bool ok = true;
  for (const auto& r : runs) ok = ok && passed(r);
  return ok ? kExitOk : kExitCosimMismatch;
}

}  // namespace rangesim::app
