// rangesim evaluate --trials / --target-error: the golden evaluation of the grid, then a Monte
// Carlo sweep of the clock-level kernels over its detectable points, every accuracy value with
// its 95% CI; journaled so that a killed or interrupted sweep resumes where it stopped.
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <fmt/format.h>
#include <thread>
#include <unistd.h>

#include "app/cli_common.h"
#include "app/commands.h"
#include "app/evaluate_params.h"
#include "app/evaluation_output.h"
#include "systemc/common/montecarlo.h"
#include "app/montecarlo/mc_evaluate.h"
#include "app/montecarlo/mc_output.h"
#include "app/montecarlo/mc_stuck_hook.h"
#include "app/montecarlo/mc_sweep.h"
#include "app/output_dir.h"
#include "app/plot.h"
#include "app/mpi_world.h"
#include "app/sweep_journal.h"
#include "core/user_error.h"
#include "golden/common/evaluate_sensor.h"

namespace rangesim::app {

namespace {

void progress(long long done, long long total, long long trials, double elapsed, double left) {
  static int last_quarter = -1;
  if (isatty(fileno(stderr))) {
    std::fprintf(stderr, "\revaluate --trials: %lld/%lld points, %lld trials, %.1f s, %s left   %s", done, total,
                 trials, elapsed, std::isfinite(left) ? fmt::format("~{:.0f} s", left).c_str() : "?",
                 done == total && left == 0 ? "\n" : "");
  } else if (int q = static_cast<int>(4 * done / std::max(total, 1LL)); q != last_quarter || left == 0) {
    last_quarter = q;
    std::fprintf(stderr, "evaluate --trials: %lld/%lld points, %lld trials, %.1f s, %s left\n", done, total, trials,
                 elapsed, std::isfinite(left) ? fmt::format("~{:.0f} s", left).c_str() : "?");
  }
}

// The command that continues this sweep: the same options with --resume.
std::string resume_command(const EvaluateOptions& o, const std::string& dir) {
  std::string c = "rangesim evaluate " + shell_quote(o.sensor);
  for (const auto& s : o.settings) c += " --set " + shell_quote(s);
  if (o.signal) c += " --signal " + shell_quote(*o.signal);
  if (o.background) c += " --background " + shell_quote(*o.background);
  if (o.samplings) c += fmt::format(" --samplings {}", *o.samplings);
  if (o.adc_bits) c += fmt::format(" --adc-bits {}", *o.adc_bits);
  if (o.frames) c += fmt::format(" --frames {}", *o.frames);
  if (o.trials) c += fmt::format(" --trials {}", *o.trials);
  if (o.target_error) c += fmt::format(" --target-error {}", *o.target_error);
  if (o.max_trials) c += fmt::format(" --max-trials {}", *o.max_trials);
  if (o.seed) c += fmt::format(" --seed {}", *o.seed);
  if (o.threads) c += fmt::format(" --threads {}", *o.threads);
  if (o.max_seconds) c += fmt::format(" --max-seconds {}", *o.max_seconds);
  if (o.json) c += " --json";
  if (o.no_plots) c += " --no-plots";
  return c + " --out " + shell_quote(dir) + " --resume";
}

// Everything that changes the sweep's results: the resolved preset and the Monte Carlo options.
std::string fingerprint(const ParamSet& params, const mc::McSweepOptions& o) {
  std::string f = fmt::format("rangesim evaluate --trials (Monte Carlo 2)\nsensor = {}\n", params.sensor_id());
  for (const auto& [key, v] : params.values())
    f += v.kind == ParamKind::Text ? fmt::format("{} = {}\n", key, v.text)
                                   : fmt::format("{} = {:.17g}\n", key, v.number);
  f += fmt::format("trials = {}\ntarget_error_m = {:.17g}\nmax_trials = {}\nseed = {}\n", o.trials, o.target_error_m,
                   o.max_trials, o.seed);
  return f;
}

}  // namespace

// Under mpirun: rank r runs the points at positions k mod N = r into a journal of its own; rank 0
// gathers every rank's journal records into the sweep's journal, from which the one output is
// made exactly as after --resume (byte-identical to a one-process run). Returns the exit code of
// an incomplete share (Ctrl-C, --max-seconds) on every rank, or -1 when all finished.
int run_mpi_share(const mpi::World& world, const mc::McModel& model, const std::vector<mc::McSweepPoint>& points,
                  const mc::McSweepOptions& sopt, const std::string& journal_dir, const std::string& fp, bool resume,
                  SweepJournal* sweep_journal) {
  std::vector<mc::McSweepPoint> mine;
  for (std::size_t k = static_cast<std::size_t>(world.rank); k < points.size();
       k += static_cast<std::size_t>(world.size))
    mine.push_back(points[k]);
  const std::string path = fmt::format("{}/evaluate.rank-{}-of-{}.journal", journal_dir, world.rank, world.size);
  const std::string rank_fp = fmt::format("{}mpi rank {} of {}\n", fp, world.rank, world.size);
  std::string records;
  int code = -1;
  {
    SweepJournal share(path, rank_fp, resume);
    const mc::McSweepResult r = mc::run_mc_sweep(model, mine, sopt, &share);
    if (!r.complete) code = r.out_of_time ? kExitBudget : stop_exit_code();
  }
  code = mpi::max_all(world, code);
  if (code >= 0) return code;  // every rank keeps its journal for --resume
  {
    SweepJournal share(path, rank_fp, true);  // read back: every finished point of this rank
    for (const auto& [index, payload] : share.done()) records += fmt::format("{} {}\n", index, payload);
    share.remove();
  }
  const std::vector<std::string> all = mpi::gather(world, records);
  if (!sweep_journal) return -1;  // ranks other than 0
  for (const auto& part : all) {
    std::istringstream in(part);
    for (std::string line; std::getline(in, line);) {
      const auto space = line.find(' ');
      const long long index = std::stoll(line.substr(0, space));
      if (!sweep_journal->done().count(index)) sweep_journal->append(index, line.substr(space + 1));
    }
  }
  return -1;
}

int run_evaluate_mc(const EvaluateOptions& opt) {
  const mpi::World world = mpi::init();
  // Validate everything before computing or touching the output directory.
  const ParamSet params = evaluate_params(opt);
  mc::McSweepOptions sopt = mc::sweep_options(opt);
  const std::unique_ptr<mc::McModel> model = mc::with_stuck_point_hook(rangesim::mc::make_mc_model(params), sopt.seed);
  const std::string dir = opt.out.empty() ? "rangesim-out/" + params.sensor_id() : opt.out;
  check_resources("evaluate --trials", evaluate_estimate(params, true), dir);
  // Every rank checks --out; rank 0 holds its lock and commits.
  OutputDir out(dir, "--out", {"evaluate", opt.force, world.rank == 0});
  const std::string journal_dir = (std::filesystem::path(dir) / ".staging-sweep").string();
  const std::string fp = fingerprint(params, sopt);
  // Under mpirun only rank 0 keeps the sweep's journal (the ranks' shares have their own).
  std::unique_ptr<SweepJournal> rank0_journal;
  if (world.rank == 0)
    rank0_journal = std::make_unique<SweepJournal>(journal_dir + "/evaluate.journal", fp, opt.resume || world.size > 1);
  if (opt.resume && rank0_journal && !rank0_journal->done().empty())
    fmt::print(stderr, "rangesim evaluate: resuming: {} points from {}\n", rank0_journal->done().size(),
               rank0_journal->path());

  const golden::EvalResult ev = golden::evaluate_sensor(params);
  const std::vector<mc::McSweepPoint> points = mc::detectable_points(ev);

  SigintGuard sigint;
  sopt.stop = &sigint_flag();
  // The time budget counts from the start of the command: what the golden grid left of it.
  if (sopt.max_seconds > 0) sopt.max_seconds = std::max(time_budget_left(), 1e-3);
  sopt.progress = world.rank == 0 ? &progress : nullptr;
  if (world.size > 1) {
    const int code = run_mpi_share(world, *model, points, sopt, journal_dir, fp, opt.resume, rank0_journal.get());
    if (code >= 0) {
      if (world.rank == 0)
        fmt::print(stderr,
                   "\nrangesim evaluate: {}: the finished points are kept in {}; to continue, run the same mpirun "
                   "line with:\n  {}\n",
                   code == kExitBudget && !sigint_flag() ? fmt::format("--max-seconds {} exceeded", *opt.max_seconds)
                                                         : stop_reason(),
                   journal_dir, resume_command(opt, dir));
      return code;
    }
    if (world.rank != 0) return kExitOk;
    sopt.progress = nullptr;  // everything comes from the journal now
  }
  SweepJournal& journal = *rank0_journal;
  const mc::McSweepResult r = mc::run_mc_sweep(*model, points, sopt, &journal);
  if (!r.complete) {
    long long have = 0;  // records in the journal (read only: abandoned workers may still append)
    std::ifstream in(journal.path());
    for (std::string line; std::getline(in, line);) have += line.rfind("P ", 0) == 0;
    fmt::print(stderr, "\nrangesim evaluate: {}: {} of {} points finished and kept in {}; nothing else written.\n",
               r.out_of_time ? fmt::format("--max-seconds {} exceeded", *opt.max_seconds) : stop_reason(), have,
               points.size(), journal.path());
    for (std::size_t k : r.stuck_points)
      fmt::print(stderr,
                 "rangesim evaluate: abandoned a trial still running {:g} s after the stop (signal {:g} {}, "
                 "background {:g} {}): ending the process now\n",
                 sopt.stop_grace_s, points[k].signal, ev.signal.unit, points[k].background, ev.background.unit);
    fmt::print(stderr, "To continue, run:\n  {}\n", resume_command(opt, dir));
    if (r.abandoned) {
      std::fflush(stderr);
      std::_Exit(r.out_of_time ? kExitBudget : stop_exit_code());  // workers still running: no unwinding
    }
    return r.out_of_time ? kExitBudget : stop_exit_code();
  }

  const mc::McGrid grid = mc::make_grid(ev, points, r, *model, sopt);

  out.write("points.csv", points_csv(ev));
  out.write("detectable_area.csv", detect_matrix_csv(ev));
  out.write("accuracy_mm.csv", accuracy_mm_matrix_csv(ev));
  for (const auto& m : ev.metric_names)
    if (m == "accuracy_px") out.write("accuracy_px.csv", metric_matrix_csv(ev, m));
  out.write("mc_points.csv", mc::mc_points_csv(grid));
  out.write("mc_golden_outside_ci.csv", mc::mc_outside_csv(grid));
  out.write("mc_accuracy_mm.csv", mc::mc_matrix_csv(grid, false));
  out.write("mc_accuracy_ci_mm.csv", mc::mc_matrix_csv(grid, true));
  std::string plot_warning;
  if (!opt.no_plots) {
    plot_warning = render_plots(out, ev);
    const std::string w = mc::render_mc_plot(out, grid);
    if (plot_warning.empty()) plot_warning = w;
  }
  nlohmann::json summary = summary_json(ev, params);
  summary["monte_carlo"] = mc::mc_summary_json(grid);
  out.write("summary.json", summary.dump(2) + "\n");
  const std::vector<std::string> written = out.commit();
  journal.remove();
  std::error_code ec;
  std::filesystem::remove(journal_dir, ec);  // only if empty
  summary["files"] = written;

  if (!plot_warning.empty()) fmt::print(stderr, "rangesim evaluate: warning: {}\n", plot_warning);
  if (r.points_capped > 0)
    fmt::print(
        stderr,
        "rangesim evaluate: warning: {} of {} points reached --max-trials {} before the 95% CI half-width of the "
        "accuracy fell to --target-error {:g} m (largest left: {:.3g} m); raise --max-trials for them\n",
        r.points_capped, points.size(), sopt.max_trials, sopt.target_error_m, r.worst_capped_half_width_m);
  if (opt.json) {
    fmt::print("{}\n", summary.dump(2));
    return 0;
  }
  fmt::print("{}\n{}outputs in {}/: ", summary_text(ev), mc::mc_summary_text(grid), dir);
  for (size_t i = 0; i < written.size(); ++i)
    fmt::print("{}{}", i ? ", " : "", written[i].substr(written[i].find_last_of('/') + 1));
  fmt::print("\n");
  return 0;
}

}  // namespace rangesim::app
