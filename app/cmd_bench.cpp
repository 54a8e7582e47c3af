// rangesim bench: the Pareto table of run time against error (every fidelity setting of every
// sensor) and the throughput ratios, each measured in one run (docs/bench.md). Exit code 0 when
// every identity check inside the bench passed; the speed targets are reported, not enforced.
#include "app/commands.h"

#include <fmt/format.h>

#include <cmath>
#include <cstdlib>
#include <optional>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <nlohmann/json.hpp>

#include "app/bench/bench_figures.h"
#include "app/bench/bench_groups.h"
#include "app/bench/bench_pareto.h"
#include "app/bench/bench_util.h"
#include "app/cli_common.h"
#include "app/output_dir.h"
#include "app/plot_style.h"
#include "app/sweep_journal.h"

namespace rangesim::app {

namespace {

using nlohmann::json;
using namespace rangesim::app::bench;

std::string value_text(const json& v) { return v.is_number() ? fmt::format("{:.4g}", v.get<double>()) : "null"; }

std::string pareto_script(const std::string& data, const std::string& ext, const std::string& path,
                          const std::vector<std::string>& sensors) {
  std::string s = fmt::format(
      "reset\nset terminal {} size 900,650 font 'Sans,11'\nset output '{}'\n{}"
      "set logscale xy\n{}{}set xlabel 'CPU time [s]'\nset ylabel 'rms range error [m]'\n"
      "set title 'rangesim bench — run time against error (a point per fidelity setting, numbered as in "
      "pareto.md)'\nset key outside right top\nset grid\nplot ",
      ext == "png" ? "pngcairo" : "svg", path, plot_preamble(), log_format("x", "s"), log_format("y", "m"));
  for (std::size_t i = 0; i < sensors.size(); ++i)
    s += fmt::format(
        "{}'{}' index {} using 1:2 with points pt 7 ps 1.3 lc rgb '{}' title '{}', '' index {} using 1:2:3 with "
        "labels font ',8' offset char 0.9,0.5 left tc rgb '{}' notitle",
        i ? ", " : "", data, i, series_colour(i), sensors[i], i, series_colour(i));
  return s + "\n";
}

// Stages pareto.{png,svg}; "" or a warning (the tables are complete without the plot).
std::string render_pareto(OutputDir& out, const std::vector<ParetoRow>& rows) {
  if (std::system("command -v gnuplot >/dev/null 2>&1") != 0)
    return "gnuplot not found: pareto plot skipped (scripts/install-deps.sh installs gnuplot-nox)";
  const std::string data = out.scratch("pareto.dat");
  std::ofstream(data) << pareto_gnuplot_data(rows);
  std::string script;
  for (const char* ext : {"png", "svg"})
    script += pareto_script(data, ext, out.staged(fmt::format("pareto.{}", ext)), pareto_sensors(rows));
  const std::string gp = out.scratch("pareto.gp");
  std::ofstream(gp) << script;
  if (std::system(fmt::format("gnuplot '{}' >'{}' 2>&1", gp, out.scratch("gnuplot.log")).c_str()) != 0)
    return "gnuplot failed: pareto plot skipped";
  return "";
}

}  // namespace

int run_bench(const BenchOptions& opt) {
  const auto t0 = Clock::now();
  set_progress_start(t0);
  const std::string dir = opt.out.empty() ? "rangesim-out/bench" : opt.out;
  OutputDir out(dir, "--out", OutputFolder{"bench", opt.force});
  // Every finished Pareto row and figure group goes to the journal: a killed or interrupted bench
  // continues with --resume and measures only what is missing.
  const std::string journal_dir = (std::filesystem::path(dir) / ".staging-sweep").string();
  SweepJournal journal(journal_dir + "/bench.journal",
                       fmt::format("rangesim bench\nquick {}\nrtl {}\n", opt.quick, RANGESIM_BENCH_HAS_RTL != 0),
                       opt.resume);
  if (!journal.done().empty())
    progress(fmt::format("resuming: {} results from {}", journal.done().size(), journal.path()));
  progress(fmt::format("start ({} run); output into {}", opt.quick ? "quick" : "full", out.dir()));
  SigintGuard sigint;  // the children die of Ctrl-C; the bench stops after them
  // A signal, or a budget that ran out, stops the bench between figure groups.
  const auto stop_requested = [] { return sigint_flag() || time_budget_left() <= 0; };
  const auto interrupted = [&] {
    const bool out_of_time = !sigint_flag();
    fmt::print(stderr,
               "rangesim bench: {}; {} results kept in {}; continue with:\n  rangesim bench{} --out {} --resume\n",
               out_of_time ? fmt::format("--max-seconds {} exceeded", run_budget().max_seconds_text) : stop_reason(),
               journal.done().size(), journal.path(), opt.quick ? " --quick" : "", shell_quote(dir));
    return out_of_time ? kExitBudget : stop_exit_code();
  };
  // A figure group from the journal, or measured now and journaled.
  const auto group = [&](long long index, const auto& measure) -> json {
    const auto it = journal.done().find(index);
    if (it != journal.done().end()) return json::parse(it->second);
    json j = measure();
    journal.append(index, j.dump());
    return j;
  };

  std::vector<ParetoRow> pareto;
  std::vector<json> results;  // one per figure group, in bench_groups() order
  const BenchGroupContext context{opt.quick, out.scratch("runs")};
  try {
    pareto = run_pareto(opt.quick, out.scratch("runs"), &journal);
    for (const BenchGroup& g : bench_groups()) {
      if (stop_requested()) return interrupted();
      results.push_back(group(g.journal_index, [&] { return g.measure(context); }));
    }
  } catch (const std::exception&) {
    if (stop_requested()) return interrupted();
    throw;
  }
  if (stop_requested()) return interrupted();

  json details, checks = json::object();
  for (std::size_t i = 0; i < results.size(); ++i) {
    const BenchGroup& g = bench_groups()[i];
    g.collect(results[i], details, checks);
    if (g.pareto_rows) g.pareto_rows(results[i], pareto);
  }
  mark_pareto(pareto);

  json j;
  for (const auto& f : all_figures()) j[f.key] = details[f.key]["value"];
  // A met flag per target (null: report only, or no value); the missed ones are printed last.
  json targets, met;
  std::vector<std::string> missed;
  for (const auto& f : all_figures()) {
    targets[f.key] = f.target;
    const std::optional<bool> m = target_met(f.target, j[f.key]);
    met[f.key] = m ? json(*m) : json(nullptr);
    if (!m || !*m)
      missed.push_back(
          fmt::format("{} = {} (target {}{})", f.key, value_text(j[f.key]), f.target, m ? "" : ", no value"));
  }
  bool all_ok = true;
  for (const auto& [k, v] : checks.items()) all_ok = all_ok && v.get<bool>();
  j["targets"] = targets;
  j["met"] = met;
  j["checks"] = checks;
  j["checks_passed"] = all_ok;
  j["quick"] = opt.quick;
  j["details"] = details;
  j["pareto"] = pareto_json(pareto);
  j["wall_s"] = seconds_since(t0);

  std::string figures_md = "| figure | value | target | met | meaning |\n|---|---:|---|---|---|\n";
  for (const auto& f : all_figures())
    figures_md += fmt::format("| `{}` | {} | {} | {} | {} |\n", f.key, value_text(j[f.key]), f.target,
                              met[f.key].is_null()     ? "—"
                              : met[f.key].get<bool>() ? "yes"
                                                       : "NO",
                              f.meaning);
  std::string checks_md;
  for (const auto& [k, v] : checks.items())
    checks_md += fmt::format("- {}: {}\n", k, v.get<bool>() ? "passed" : "FAILED");

  out.write("bench.json", j.dump(2) + "\n");
  out.write("figures.md", figures_md);
  out.write("pareto.md", pareto_markdown(pareto));
  out.write("pareto.csv", pareto_csv(pareto));
  const std::string warning = render_pareto(out, pareto);
  out.commit();
  journal.remove();
  std::error_code ec;
  std::filesystem::remove(journal_dir, ec);  // only if empty
  progress(fmt::format("done in {:.1f} s", seconds_since(t0)));

  if (opt.json) {
    std::cout << j.dump(2) << "\n";
  } else {
    fmt::print("rangesim bench ({}), {:.1f} s; files in {}\n\n{}\nIdentity checks:\n{}\n{}",
               opt.quick ? "quick" : "full", seconds_since(t0), out.dir(), figures_md, checks_md,
               pareto_markdown(pareto));
  }
  if (!warning.empty()) fmt::print(stderr, "rangesim: warning: {}\n", warning);
  // The speed targets are reported, not enforced (exit 0 either way); the missed ones come last
  // (stderr with --json, whose stdout is the JSON).
  if (!missed.empty()) {
    std::string text = fmt::format("\nTargets missed ({} of {}):\n", missed.size(), all_figures().size());
    for (const auto& m : missed) text += "  " + m + "\n";
    if (opt.json)
      fmt::print(stderr, "{}", text);
    else
      fmt::print("{}", text);
  }
  if (!all_ok) fmt::print(stderr, "rangesim: bench: an identity check failed (see checks in bench.json)\n");
  return all_ok ? 0 : 1;
}

}  // namespace rangesim::app
