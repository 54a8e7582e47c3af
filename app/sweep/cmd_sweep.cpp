// rangesim sweep and rangesim merge: architecture variants of one preset (app/sweep/sweep_spec.h),
// each evaluated through the sensor's golden model and clock schedule (sweep_run.h), written as one
// table and plots (sweep_output.h). Every finished variant goes to a journal, so a killed sweep
// resumes with identical output; --shard K/N computes every N-th variant for batch arrays, and
// merge combines the shards into the output of the unsharded run.
#include <fmt/format.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <thread>
#include <sstream>

#include "app/cli_common.h"
#include "app/commands.h"
#include "app/evaluate_params.h"
#include "app/mpi_world.h"
#include "app/sweep/sweep_output.h"
#include "app/sweep/sweep_spec.h"
#include "app/sweep_journal.h"
#include "core/input_file.h"
#include "core/preset.h"
#include "core/user_error.h"

namespace rangesim::app {

namespace {

namespace fs = std::filesystem;
using namespace rangesim::app::sweep;
using Clock = std::chrono::steady_clock;

struct Shard {
  long long k = 1, n = 1;  // this process computes the variants i with i % n == k - 1
};

Shard parse_shard(const std::optional<std::string>& text) {
  if (!text) return {};
  Shard s;
  char slash = 0, extra = 0;
  std::istringstream in(*text);
  if (!(in >> s.k >> slash >> s.n) || slash != '/' || (in >> extra) || s.n < 1 || s.n > 100000 || s.k < 1 || s.k > s.n)
    throw UserError(fmt::format("--shard {}: expected K/N with 1 <= K <= N <= 100000, e.g. --shard 2/8", *text));
  return s;
}

// The Monte Carlo and co-simulation options of a sweep, checked.
VariantChecks variant_checks(const SweepOptions& o) {
  VariantChecks c;
  if (o.trials) {
    if (*o.trials < 2 || *o.trials > 10000000)
      throw UserError(fmt::format("--trials {}: allowed 2 .. 10000000", *o.trials));
    c.trials = *o.trials;
  }
  c.seed = o.seed;
  c.threads = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  c.cosim = o.cosim;
  if (o.cosim_cycles < 1 || o.cosim_cycles > 1000000000)
    throw UserError(fmt::format("--cosim-cycles {}: allowed 1 .. 1000000000", o.cosim_cycles));
  c.cosim_cycles = o.cosim_cycles;
  c.settings = o.settings;
  return c;
}

// Everything that changes the rows: the resolved preset, the assignments, the variant list and
// the Monte Carlo and co-simulation options.
std::string fingerprint(const ParamSet& base, const SweepHeader& h, const std::vector<std::vector<std::string>>& vars) {
  std::string f = fmt::format("rangesim sweep 1\nsensor = {}\ntrials = {}\nseed = {}\ncosim = {} {}\n",
                              base.sensor_id(), h.checks.trials, h.checks.seed, h.checks.cosim, h.checks.cosim_cycles);
  for (const auto& [key, v] : base.values())
    f += v.kind == ParamKind::Text ? fmt::format("{} = {}\n", key, v.text)
                                   : fmt::format("{} = {:.17g}\n", key, v.number);
  for (const auto& s : h.settings) f += "set " + s + "\n";
  for (const auto& v : vars) {
    f += "variant";
    for (const auto& a : v) f += " " + a;
    f += "\n";
  }
  return f;
}

// Progress on stderr: from 2 s on, at most once a second, with the time left.
struct SweepProgress {
  Clock::time_point start = Clock::now(), last = start;
  long long total = 0;
  bool quiet = false;  // MPI ranks other than 0
  void operator()(long long done, long long from_journal) {
    if (quiet) return;
    const auto now = Clock::now();
    const double t = std::chrono::duration<double>(now - start).count();
    if (done != total && (t < 2 || now - last < std::chrono::seconds(1))) return;
    last = now;
    const long long computed = done - from_journal;
    const double left = computed > 0 ? t / computed * (total - done) : 0;
    fmt::print(stderr, "sweep: {}/{} variants, {:.1f} s, ~{:.0f} s left\n", done, total, t, left);
  }
};

std::string resume_command(const SweepOptions& o, const std::string& dir) {
  std::string c = "rangesim sweep " + shell_quote(o.sensor);
  for (const auto& s : o.settings) c += " --set " + shell_quote(s);
  for (const auto& v : o.vary) c += " --vary " + shell_quote(v);
  if (o.zip) c += " --zip";
  if (o.shard) c += " --shard " + *o.shard;
  if (o.json) c += " --json";
  if (o.no_plots) c += " --no-plots";
  if (o.pareto_accuracy != "min") c += " --pareto-accuracy " + o.pareto_accuracy;
  if (o.trials) c += fmt::format(" --trials {} --seed {}", *o.trials, o.seed);
  if (o.cosim) c += fmt::format(" --cosim --cosim-cycles {}", o.cosim_cycles);
  return c + " --out " + shell_quote(dir) + " --resume";
}

// The unsharded outputs from every row: sweep.csv, sweep.json, plots; then the table or JSON.
int write_outputs(OutputDir& out, const SweepHeader& h, const std::vector<SweepRow>& rows, bool json, bool no_plots) {
  const nlohmann::json j = sweep_json(h, rows);
  out.write("sweep.csv", sweep_csv(h, rows));
  out.write("sweep.json", j.dump(2) + "\n");
  const std::string warning = no_plots ? "" : render_sweep_plots(out, h, rows);
  const std::vector<std::string> written = out.commit();
  if (!warning.empty()) fmt::print(stderr, "rangesim sweep: warning: {}\n", warning);
  if (json) {
    fmt::print("{}\n", j.dump(2));
    return kExitOk;
  }
  fmt::print("{}\noutputs in {}/: ", sweep_text(h, rows), out.dir());
  for (std::size_t i = 0; i < written.size(); ++i)
    fmt::print("{}{}", i ? ", " : "", fs::path(written[i]).filename().string());
  fmt::print("\n");
  return kExitOk;
}

nlohmann::json header_json(const SweepHeader& h) {
  return {{"sensor", h.sensor},
          {"preset", h.preset},
          {"set", h.settings},
          {"varied", h.keys},
          {"zip", h.zip},
          {"trials", h.checks.trials},
          {"seed", h.checks.seed},
          {"cosim", h.checks.cosim},
          {"cosim_cycles", h.checks.cosim_cycles}};
}

SweepHeader header_from_json(const nlohmann::json& j) {
  SweepHeader h{j.at("sensor"), j.at("preset"), j.at("set").get<std::vector<std::string>>(),
                j.at("varied").get<std::vector<std::string>>(), j.at("zip").get<bool>()};
  h.checks.trials = j.at("trials"), h.checks.seed = j.at("seed"), h.checks.cosim = j.at("cosim");
  h.checks.cosim_cycles = j.at("cosim_cycles");
  return h;
}

// One shard file: its rows appended to `rows`; the header, fingerprint and variant count taken
// from the first shard (`h` empty) or checked against it. Any malformed content is bad input.
Shard read_shard(const std::string& path, std::vector<SweepRow>& rows, std::optional<SweepHeader>& h,
                 std::uint64_t& hash, long long& total, const std::string& first) {
  constexpr std::uintmax_t kMaxShardBytes = 1ull << 30;  // a million variants of JSON rows
  const std::string text = read_input_file(path, "the shard file", kMaxShardBytes, "merge: " + path);
  try {
    const nlohmann::json j = nlohmann::json::parse(text);
    if (!j.contains("rangesim_sweep_shard")) throw std::runtime_error("no rangesim_sweep_shard key");
    Shard s{j.at("shard").get<long long>(), j.at("shards").get<long long>()};
    if (s.n < 1 || s.n > 100000 || s.k < 1 || s.k > s.n)
      throw std::runtime_error(fmt::format("shard {}/{}; allowed K/N with 1 <= K <= N <= 100000", s.k, s.n));
    if (!h) {
      h = header_from_json(j.at("header")), hash = j.at("fingerprint_hash"), total = j.at("variants_total");
    } else if (j.at("fingerprint_hash").get<std::uint64_t>() != hash) {
      throw UserError(fmt::format(
          "merge: {}: shard of another sweep (preset, --set, --vary or shard count differ from {})", path, first));
    }
    for (const auto& r : j.at("rows")) rows.push_back(row_from_json(r, h->checks));
    return s;
  } catch (const UserError&) {
    throw;
  } catch (const std::exception& e) {
    throw UserError(fmt::format("merge: {}: not a rangesim sweep shard ({})", path, e.what()));
  }
}

}  // namespace

int run_sweep(const SweepOptions& opt) {
  const mpi::World world = mpi::init();
  ParamSet base = load_modelled_preset(opt.sensor, "sweep", opt.settings);
  const ParamSchema& schema = schema_for(base.sensor_id(), base.origin());
  if (opt.vary.empty()) throw UserError("--vary is required: KEY=LO:HI:N[:log] or KEY=v1,v2,... (repeatable)");
  std::vector<VaryAxis> axes;
  SweepHeader h{base.sensor_id(), base.origin(), opt.settings, {}, opt.zip, "accuracy_" + opt.pareto_accuracy + "_m"};
  h.checks = variant_checks(opt);
  for (const auto& v : opt.vary) {
    axes.push_back(parse_vary(v, schema));
    for (const auto& k : h.keys)
      if (k == axes.back().key) throw UserError(fmt::format("--vary {}: {} is varied twice", v, k));
    h.keys.push_back(axes.back().key);
  }
  const auto vars = variants(axes, opt.zip, 1000000);
  Shard shard = parse_shard(opt.shard);
  if (world.size > 1) {
    if (opt.shard) throw UserError("--shard under mpirun: the ranks are the shards; give one or the other");
    shard = {world.rank + 1, world.size};
  }
  const std::string dir = opt.out.empty() ? "rangesim-out/sweep/" + base.sensor_id() : opt.out;
  ResourceEstimate estimate = evaluate_estimate(base, h.checks.trials > 0);
  estimate.memory_bytes += static_cast<double>(vars.size()) * 2048;  // the rows, their JSON and the journal index
  estimate.disk_bytes = static_cast<double>(vars.size()) * 1024;
  estimate.what = fmt::format("{} variants of ~2 KiB, each evaluating {}", vars.size(), estimate.what);
  estimate.reduce = "--vary (fewer values), or " + estimate.reduce;
  if (world.rank == 0) check_resources("sweep", estimate, dir);
  std::unique_ptr<OutputDir> out;  // rank 0 writes; the other ranks only journal their share
  // A shard's file is not the sweep's output: shards into one folder are refused, not replaced.
  const std::string kind =
      shard.n > 1 && world.size == 1 ? fmt::format("sweep --shard {}/{}", shard.k, shard.n) : "sweep";
  if (world.rank == 0) out = std::make_unique<OutputDir>(dir, "--out", OutputFolder{kind, opt.force});
  const std::string fp = fingerprint(base, h, vars);
  SweepJournal journal(
      (fs::path(dir) / ".staging-sweep" / fmt::format("sweep.{}-of-{}.journal", shard.k, shard.n)).string(), fp,
      opt.resume);
  SigintGuard sigint;
  SweepProgress progress;
  progress.quiet = world.rank != 0;
  std::vector<SweepRow> rows;
  for (long long i = shard.k - 1; i < static_cast<long long>(vars.size()); i += shard.n) ++progress.total;
  long long from_journal = 0;
  int stopped = 0;  // exit code of a stop between variants (a signal, a budget), 0 while running
  for (long long i = shard.k - 1; i < static_cast<long long>(vars.size()); i += shard.n) {
    if (sigint_flag()) stopped = stop_exit_code();
    if (time_budget_left() <= 0) stopped = kExitBudget;
    if (stopped) break;
    const auto it = journal.done().find(i);
    if (it != journal.done().end()) {
      rows.push_back(row_from_json(nlohmann::json::parse(it->second), h.checks));
      ++from_journal;
    } else {
      rows.push_back(run_variant(base, i, vars[static_cast<std::size_t>(i)], h.checks));
      journal.append(i, row_json(rows.back(), h.checks).dump());
    }
    progress(static_cast<long long>(rows.size()), from_journal);
  }
  if (const int code = mpi::max_all(world, stopped); code != 0) {
    const std::string why = stopped == kExitBudget && !sigint_flag()
                                ? fmt::format("--max-seconds {} exceeded", run_budget().max_seconds_text)
                                : stop_reason();
    if (world.rank == 0)
      fmt::print(stderr, "rangesim sweep: {}; finished variants kept in {}; continue with:\n  {}{}\n", why,
                 fs::path(journal.path()).parent_path().string(), world.size > 1 ? "mpirun ... " : "",
                 resume_command(opt, dir));
    return code;
  }
  if (world.size > 1) {  // rank 0 gathers every rank's rows, in variant order
    nlohmann::json mine = nlohmann::json::array();
    for (const auto& r : rows) mine.push_back(row_json(r, h.checks));
    const std::vector<std::string> parts = mpi::gather(world, mine.dump());
    journal.remove();
    if (world.rank != 0) return kExitOk;
    rows.clear();
    for (const auto& part : parts)
      for (const auto& r : nlohmann::json::parse(part)) rows.push_back(row_from_json(r, h.checks));
    std::sort(rows.begin(), rows.end(), [](const SweepRow& a, const SweepRow& b) { return a.index < b.index; });
  } else if (shard.n > 1) {
    nlohmann::json part = {{"rangesim_sweep_shard", 1},
                           {"fingerprint_hash", SweepJournal::hash(fp)},
                           {"shard", shard.k},
                           {"shards", shard.n},
                           {"variants_total", vars.size()},
                           {"header", header_json(h)},
                           {"rows", nlohmann::json::array()}};
    for (const auto& r : rows) part["rows"].push_back(row_json(r, h.checks));
    const std::string name = fmt::format("sweep.shard-{}-of-{}.json", shard.k, shard.n);
    out->write(name, part.dump(1) + "\n");
    out->commit();
    journal.remove();
    fmt::print("shard {}/{}: {} of {} variants in {}; combine the shards with `rangesim merge --out DIR PART...`\n",
               shard.k, shard.n, rows.size(), vars.size(), (fs::path(dir) / name).string());
    return kExitOk;
  }
  const int code = write_outputs(*out, h, rows, opt.json, opt.no_plots);
  journal.remove();
  return code;
}

int run_merge(const MergeOptions& opt) {
  if (opt.parts.empty())
    throw UserError("merge: give the shard files, e.g. rangesim merge --out DIR part1/sweep.shard-1-of-2.json ...");
  // The output folder first: a bad --out is refused before the shards are read.
  OutputDir out(opt.out.empty() ? "rangesim-out/sweep/merged" : opt.out, "--out", OutputFolder{"sweep", opt.force});
  std::vector<SweepRow> rows;
  std::optional<SweepHeader> h;
  std::uint64_t hash = 0;
  long long shards = 0, total = 0;
  std::vector<bool> seen;
  for (const auto& path : opt.parts) {
    const Shard shard = read_shard(path, rows, h, hash, total, opt.parts.front());
    if (seen.empty()) {
      shards = shard.n;
      seen.assign(static_cast<std::size_t>(shard.n), false);
    } else if (shard.n != shards) {
      throw UserError(fmt::format("merge: {}: shard of another sweep ({} shards, {} has {})", path, shard.n,
                                  opt.parts.front(), shards));
    }
    if (seen[static_cast<std::size_t>(shard.k - 1)])
      throw UserError(fmt::format("merge: {}: shard {}/{} given twice", path, shard.k, shard.n));
    seen[static_cast<std::size_t>(shard.k - 1)] = true;
  }
  std::string missing;
  for (std::size_t k = 0; k < seen.size(); ++k)
    if (!seen[k]) missing += fmt::format("{}{}/{}", missing.empty() ? "" : ", ", k + 1, shards);
  if (!missing.empty())
    throw UserError(fmt::format("merge: shards missing: {}; allowed: all {} shards once", missing, shards));
  std::sort(rows.begin(), rows.end(), [](const SweepRow& a, const SweepRow& b) { return a.index < b.index; });
  if (static_cast<long long>(rows.size()) != total)
    throw UserError(fmt::format("merge: the shards hold {} variants, the sweep has {}", rows.size(), total));
  h->pareto_accuracy = "accuracy_" + opt.pareto_accuracy + "_m";
  return write_outputs(out, *h, rows, opt.json, opt.no_plots);
}

}  // namespace rangesim::app
