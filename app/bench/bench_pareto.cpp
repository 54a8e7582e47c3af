#include "app/bench/bench_pareto.h"

#include <fmt/format.h>

#include <cmath>
#include <algorithm>
#include <map>

#include "app/bench/bench_util.h"
#include "core/sensor_list.h"

namespace rangesim::app::bench {

// Each shipped sensor's settings, defined in app/bench/pareto_<sensor>.cpp.
#define RANGESIM_DECLARE(s) std::vector<ParetoSetting> s##_pareto_settings(bool quick);
RANGESIM_FOR_EACH_SENSOR(RANGESIM_DECLARE)
#undef RANGESIM_DECLARE

namespace {

// Every sensor's settings, in registry order (core/sensor_list.h).
std::vector<ParetoSetting> settings(bool quick) {
  std::vector<ParetoSetting> s;
#define RANGESIM_APPEND(x) \
  for (ParetoSetting & r : x##_pareto_settings(quick)) s.push_back(std::move(r));
  RANGESIM_FOR_EACH_SENSOR(RANGESIM_APPEND)
#undef RANGESIM_APPEND
  return s;
}

std::string num(double v) { return std::isfinite(v) ? fmt::format("{:.4g}", v) : ""; }

}  // namespace

std::string pareto_row_record(const ParetoRow& r) {
  const nlohmann::json j = {
      {"sensor", r.sensor}, {"setting", r.setting}, {"harness", r.harness}, {"args", r.args},     {"frames", r.frames},
      {"wall_s", r.wall_s}, {"cpu_s", r.cpu_s},     {"error_m", r.error_m}, {"points", r.points}, {"note", r.note}};
  return j.dump();  // NaN error -> null
}

ParetoRow pareto_row_from_record(const std::string& record) {
  const nlohmann::json j = nlohmann::json::parse(record);
  ParetoRow r;
  r.sensor = j.at("sensor"), r.setting = j.at("setting"), r.harness = j.at("harness");
  r.args = j.at("args").get<std::vector<std::string>>();
  r.frames = j.at("frames"), r.wall_s = j.at("wall_s"), r.cpu_s = j.at("cpu_s");
  r.error_m = j.at("error_m").is_number() ? j.at("error_m").get<double>() : NAN;
  r.points = j.at("points"), r.note = j.at("note");
  return r;
}

std::vector<ParetoRow> run_pareto(bool quick, const std::string& scratch_dir, SweepJournal* journal) {
  std::vector<ParetoRow> rows;
  int i = 0;
  const auto all = settings(quick);
  for (const ParetoSetting& s : all) {
    if (journal && journal->done().count(i)) {
      progress(fmt::format("pareto {}/{}: {} {} (from the journal)", ++i, all.size(), s.sensor, s.setting));
      rows.push_back(pareto_row_from_record(journal->done().at(i - 1)));
      continue;
    }
    ParetoRow r;
    r.sensor = s.sensor, r.setting = s.setting, r.harness = s.harness;
    r.args = {"--scene", scene_path(s.scene)};
    r.args.insert(r.args.end(), s.extra.begin(), s.extra.end());
    progress(fmt::format("pareto {}/{}: {} {}", ++i, all.size(), s.sensor, s.setting));
    std::vector<std::string> argv = {"simulate", s.sensor};
    argv.insert(argv.end(), r.args.begin(), r.args.end());
    argv.insert(argv.end(), {"--json", "--no-plots", "--out", fmt::format("{}/run{}", scratch_dir, i)});
    const SelfRun run = run_self_timed(argv);
    r.wall_s = run.wall_s;
    r.cpu_s = run.cpu_s;
    if (run.exit_code != 0)
      throw std::runtime_error(
          fmt::format("bench: rangesim simulate {} {} failed with exit code {}", s.sensor, s.setting, run.exit_code));
    const nlohmann::json j = nlohmann::json::parse(run.out);
    r.frames = j.value("frames", 0LL);
    const auto& e = j["range_error_rms_m"];
    r.error_m = e.is_number() ? e.get<double>() : NAN;
    for (const char* key : {"points_detected", "detected"})
      if (j.contains(key) && j[key].is_number()) r.points = j[key].get<long long>();
    if (journal) journal->append(i - 1, pareto_row_record(r));
    rows.push_back(r);
  }
  return rows;
}

void mark_pareto(std::vector<ParetoRow>& rows) {
  for (auto& a : rows) {
    a.pareto = std::isfinite(a.error_m);
    for (const auto& b : rows)
      if (&a != &b && a.pareto && b.sensor == a.sensor && std::isfinite(b.error_m) && b.cpu_s <= a.cpu_s &&
          b.error_m <= a.error_m && (b.cpu_s < a.cpu_s || b.error_m < a.error_m))
        a.pareto = false;
  }
}

std::string pareto_markdown(const std::vector<ParetoRow>& rows) {
  // `#` is the number pareto.png labels the row's point with.
  std::string s =
      "| # | sensor | setting | harness | frames | CPU time (s) | wall time (s) | rms range error (m) | Pareto |\n"
      "|---:|---|---|---|---:|---:|---:|---:|:-:|\n";
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const ParetoRow& r = rows[i];
    s += fmt::format("| {} | {} | {} | {} | {} | {} | {} | {} | {} |\n", i + 1, r.sensor, r.setting, r.harness,
                     r.frames, num(r.cpu_s), num(r.wall_s), std::isfinite(r.error_m) ? num(r.error_m) : "none detected",
                     r.pareto ? "yes" : "");
  }
  return s;
}

std::string pareto_csv(const std::vector<ParetoRow>& rows) {
  std::string s = "sensor,setting,harness,frames,cpu_s,wall_s,error_rms_m,pareto,note\n";
  for (const auto& r : rows)
    s += fmt::format("{},\"{}\",{},{},{},{},{},{},\"{}\"\n", r.sensor, r.setting, r.harness, r.frames, num(r.cpu_s),
                     num(r.wall_s), num(r.error_m), r.pareto ? 1 : 0, r.note);
  return s;
}

nlohmann::json pareto_json(const std::vector<ParetoRow>& rows) {
  nlohmann::json a = nlohmann::json::array();
  for (const auto& r : rows) {
    nlohmann::json j{{"sensor", r.sensor}, {"setting", r.setting}, {"harness", r.harness}, {"frames", r.frames},
                     {"cpu_s", r.cpu_s},   {"wall_s", r.wall_s},   {"pareto", r.pareto}};
    j["error_rms_m"] = std::isfinite(r.error_m) ? nlohmann::json(r.error_m) : nlohmann::json(nullptr);
    if (!r.note.empty()) j["note"] = r.note;
    a.push_back(j);
  }
  return a;
}

std::vector<std::string> pareto_sensors(const std::vector<ParetoRow>& rows) {
  std::vector<std::string> order;
  for (const auto& r : rows)
    if (std::find(order.begin(), order.end(), r.sensor) == order.end()) order.push_back(r.sensor);
  return order;
}

std::string pareto_gnuplot_data(const std::vector<ParetoRow>& rows) {
  // One gnuplot data block per sensor (index i), columns: cpu_s error_m "row number in pareto.md"
  // (setting names as labels overlap where points crowd; a number stays readable).
  std::map<std::string, std::vector<std::size_t>> by;
  for (std::size_t i = 0; i < rows.size(); ++i) by[rows[i].sensor].push_back(i);
  std::string s;
  for (const auto& name : pareto_sensors(rows)) {
    s += fmt::format("# {}\n", name);
    for (std::size_t i : by[name])
      if (std::isfinite(rows[i].error_m))
        s += fmt::format("{:.6g} {:.6g} \"{}\"\n", rows[i].cpu_s, rows[i].error_m, i + 1);
    s += "\n\n";
  }
  return s;
}

}  // namespace rangesim::app::bench
