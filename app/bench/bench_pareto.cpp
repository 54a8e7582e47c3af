#include "app/bench/bench_pareto.h"

#include <fmt/format.h>

#include <cmath>
#include <algorithm>
#include <map>

#include "app/bench/bench_util.h"

namespace rangesim::app::bench {

namespace {

struct Setting {
  std::string sensor, scene, setting, harness;
  std::vector<std::string> extra;
};

// tof-lockin with the pulse/gate overlaps integrated numerically at a time step (`simulate
// --time-step`) instead of in closed form: 50 ns (half the preset's T0: the windows' charge is
// wrong by up to a step), 10 ns and 0.1 ns (1000 steps per pulse); --quick leaves out the finest.
std::vector<Setting> lockin_time_step_settings(bool quick) {
  std::vector<Setting> s;
  for (const char* step : {"5e-08", "1e-08", "1e-10"}) {
    if (quick && std::string(step) == "1e-10") continue;
    s.push_back({"tof-lockin", "tof-lockin-plane.toml", fmt::format("kernel, aggregated, time step {} s", step), "kernel",
                 {"--kernel-only", "--time-step", step}});
  }
  return s;
}

std::vector<Setting> settings(bool quick) {
  const std::string lf = quick ? "25" : "75";  // ls-conventional frame accesses (a fifth of the map in the full run)
  // Quick: the slow per-clock references of ls-demodulation and tof-lockin are left out (they
  // take minutes); the full run has every row.
  std::vector<Setting> s = {
      {"ls-conventional", "plane.toml", "kernel, sparse, event skipping", "kernel", {"--kernel-only", "--frames", lf}},
      {"ls-conventional", "plane.toml", "kernel, dense", "kernel", {"--kernel-only", "--no-sparse", "--frames", lf}},
      {"ls-conventional", "plane.toml", "kernel, per clock", "kernel", {"--kernel-only", "--no-event-skip", "--frames", lf}},
      {"ls-conventional", "plane.toml", "kernel, noise-free", "kernel", {"--kernel-only", "--noise-free", "--frames", lf}},
      {"ls-conventional", "plane.toml", "SystemC module", "systemc", {"--frames", quick ? "10" : "60"}},
      {"ls-demodulation", "ls-demodulation-plane.toml", "kernel, event skipping, 1 frame", "kernel", {"--kernel-only", "--frames", "1"}},
      {"ls-demodulation", "ls-demodulation-plane.toml", "kernel, event skipping, 4 frames", "kernel", {"--kernel-only", "--frames", "4"}},
      {"ls-demodulation", "ls-demodulation-plane.toml", "SystemC module, 1 frame", "systemc", {"--frames", "1"}},
      {"ls-demodulation", "ls-demodulation-plane.toml", "kernel, per period (no aggregation)", "kernel",
       {"--kernel-only", "--no-aggregate", "--frames", "1"}},
      {"tof-lockin", "tof-lockin-plane.toml", "kernel, aggregated", "kernel", {"--kernel-only"}},
      {"tof-lockin", "tof-lockin-plane.toml", "SystemC module", "systemc", {}},
      {"tof-spad", "tof-spad-plane.toml", "kernel, 1 frame", "kernel", {"--kernel-only", "--frames", "1"}},
      {"tof-spad", "tof-spad-plane.toml", "kernel, 4 frames", "kernel", {"--kernel-only", "--frames", "4"}},
      {"tof-spad", "tof-spad-plane.toml", "SystemC module, 1 frame", "systemc", {"--frames", "1"}},
      // Beam spot: the window (512 pixels, 448 background-only) against the whole array one by one.
      {"tof-spad", "tof-spad-spot.toml", "kernel, beam spot, sparse", "kernel", {"--kernel-only"}},
  };
  if (!quick) {
    s.push_back({"ls-demodulation", "ls-demodulation-plane.toml", "kernel, per clock, 1 frame", "kernel",
                 {"--kernel-only", "--no-event-skip", "--frames", "1"}});
    s.push_back({"tof-lockin", "tof-lockin-plane.toml", "kernel, no aggregation", "kernel", {"--kernel-only", "--no-aggregate"}});
    s.push_back({"tof-spad", "tof-spad-plane.toml", "kernel, 16 frames", "kernel", {"--kernel-only", "--frames", "16"}});
    s.push_back({"tof-spad", "tof-spad-spot.toml", "kernel, beam spot, dense", "kernel", {"--kernel-only", "--dense"}});
  }
  for (Setting& t : lockin_time_step_settings(quick)) s.push_back(std::move(t));
  std::stable_sort(s.begin(), s.end(), [](const Setting& a, const Setting& b) { return a.sensor < b.sensor; });
  return s;
}

std::string num(double v) { return std::isfinite(v) ? fmt::format("{:.4g}", v) : ""; }

}  // namespace

std::string pareto_row_record(const ParetoRow& r) {
  const nlohmann::json j = {{"sensor", r.sensor}, {"setting", r.setting}, {"harness", r.harness}, {"args", r.args},
                            {"frames", r.frames},   {"wall_s", r.wall_s},   {"cpu_s", r.cpu_s},     {"error_m", r.error_m},
                            {"points", r.points},   {"note", r.note}};
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
  for (const Setting& s : all) {
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
    std::string text;
    const auto t0 = Clock::now();
    const double c0 = children_cpu_now();
    const int code = run_self(argv, text);
    r.wall_s = seconds_since(t0);
    r.cpu_s = children_cpu_now() - c0;
    if (code != 0) throw std::runtime_error(fmt::format("bench: rangesim simulate {} {} failed with exit code {}", s.sensor, s.setting, code));
    const nlohmann::json j = nlohmann::json::parse(text);
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
  std::string s =
      "| sensor | setting | harness | frames | CPU time (s) | wall time (s) | rms range error (m) | Pareto |\n"
      "|---|---|---|---:|---:|---:|---:|:-:|\n";
  for (const auto& r : rows)
    s += fmt::format("| {} | {} | {} | {} | {} | {} | {} | {} |\n", r.sensor, r.setting, r.harness, r.frames, num(r.cpu_s), num(r.wall_s),
                     std::isfinite(r.error_m) ? num(r.error_m) : "none detected", r.pareto ? "yes" : "");
  return s;
}

std::string pareto_csv(const std::vector<ParetoRow>& rows) {
  std::string s = "sensor,setting,harness,frames,cpu_s,wall_s,error_rms_m,pareto,note\n";
  for (const auto& r : rows)
    s += fmt::format("{},\"{}\",{},{},{},{},{},{},\"{}\"\n", r.sensor, r.setting, r.harness, r.frames, num(r.cpu_s), num(r.wall_s), num(r.error_m),
                     r.pareto ? 1 : 0, r.note);
  return s;
}

nlohmann::json pareto_json(const std::vector<ParetoRow>& rows) {
  nlohmann::json a = nlohmann::json::array();
  for (const auto& r : rows) {
    nlohmann::json j{{"sensor", r.sensor}, {"setting", r.setting}, {"harness", r.harness}, {"frames", r.frames},
                     {"cpu_s", r.cpu_s}, {"wall_s", r.wall_s}, {"pareto", r.pareto}};
    j["error_rms_m"] = std::isfinite(r.error_m) ? nlohmann::json(r.error_m) : nlohmann::json(nullptr);
    if (!r.note.empty()) j["note"] = r.note;
    a.push_back(j);
  }
  return a;
}

std::string pareto_gnuplot_data(const std::vector<ParetoRow>& rows) {
  // One gnuplot data block per sensor (index i), columns: wall_s error_m "label".
  std::map<std::string, std::vector<const ParetoRow*>> by;
  std::vector<std::string> order;
  for (const auto& r : rows) {
    if (!by.count(r.sensor)) order.push_back(r.sensor);
    by[r.sensor].push_back(&r);
  }
  std::string s;
  for (const auto& name : order) {
    s += fmt::format("# {}\n", name);
    for (const ParetoRow* r : by[name])
      if (std::isfinite(r->error_m)) s += fmt::format("{:.6g} {:.6g} \"{}\"\n", r->cpu_s, r->error_m, r->setting);
    s += "\n\n";
  }
  return s;
}

}  // namespace rangesim::app::bench
