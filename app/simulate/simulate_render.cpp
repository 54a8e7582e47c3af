#include "app/simulate/simulate_render.h"

#include <fmt/format.h>

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <exception>
#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>
#include <thread>
#include <utility>

#include "app/cli_common.h"
#include "app/output_dir.h"
#include "app/resource_estimate.h"
#include "app/simulate/npy_writer.h"
#include "app/simulate/png_writer.h"
#include "app/simulate/simulate_output.h"
#include "app/simulate/simulate_report.h"
#include "app/simulate/trace_output.h"
#include "systemc/common/simulation.h"

namespace rangesim::app {

systemc::SimulationRequest simulation_request(const SimulateOptions& opt) {
  systemc::SimulationRequest r;
  r.scene = opt.scene;
  r.frames = opt.frames;
  r.seed = opt.seed;
  r.kernel_only = opt.kernel_only;
  r.tick = opt.tick;
  r.noise_free = opt.noise_free;
  r.dense = opt.dense;
  r.no_aggregate = opt.no_aggregate;
  r.time_step_s = opt.time_step_s;
  r.threads = opt.threads.value_or(static_cast<int>(std::max(1u, std::thread::hardware_concurrency())));
  r.trace_rows = opt.trace_rows;
  r.trace_pixels = opt.trace_pixels;
  return r;
}

namespace {

// The command as the scene run's host: it owns the trace and the output folder the run claims
// (the trace is declared first, so the folder is cleaned up before it, as before).
class CommandHost : public systemc::SimulationHost {
 public:
  explicit CommandHost(const SimulateOptions& opt) : opt_(opt), start_(Progress::Clock::now()) {}

  std::string open_trace() override {
    trace_.emplace(opt_.trace, opt_.kernel_only);
    return trace_->vcd_base();
  }
  void open_output(const std::string& scene_name) override {
    out_.emplace(opt_.out.empty() ? "rangesim-out/simulate/" + scene_name : opt_.out, "--out",
                 OutputFolder{"simulate", opt_.force});
  }
  std::function<void(long long)> progress(const std::string& unit, long long total) override {
    auto p = std::make_shared<Progress>(unit, total, start_);
    return [p](long long done) { (*p)(done); };
  }
  void check_memory(double bytes, const std::string& what, const std::string& reduce) override {
    check_resources("simulate", {kBaseMemoryBytes + bytes, 0, what, reduce}, "");
  }

  OutputDir& out() {
    if (!out_) throw std::logic_error("simulate: the scene run returned without claiming the output folder");
    return *out_;
  }
  TraceOutput& trace() {
    if (!trace_) trace_.emplace("", opt_.kernel_only);  // a run that never traces: no-op
    return *trace_;
  }

 private:
  const SimulateOptions& opt_;
  Progress::Clock::time_point start_;  // start of the run (progress lines count from here)
  std::optional<TraceOutput> trace_;   // --trace, once the run has checked its flags
  std::optional<OutputDir> out_;       // --out, once the scene is known
};

// CPU time of this process and of its waited-for children (gnuplot), s.
double cpu_with_children_s() {
  double s = 0;
  for (const int who : {RUSAGE_SELF, RUSAGE_CHILDREN}) {
    rusage u{};
    ::getrusage(who, &u);
    for (const timeval& t : {u.ru_utime, u.ru_stime})
      s += static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_usec);
  }
  return s;
}

// A table of `values` numbers goes out as .npy (true) or CSV.
bool as_npy(const SimulateOptions& opt, std::size_t values) { return opt.npy || (!opt.csv && values > kNpyMinValues); }

// One output written on a thread of its own while the caller writes the others; joined (and its
// failure rethrown) by join(), or on the way out of a failed caller.
class Background {
 public:
  void start(std::function<void()> job) {
    thread_ = std::thread([this, job = std::move(job)] {
      try {
        job();
      } catch (...) {
        failure_ = std::current_exception();
      }
    });
  }
  void join() {
    if (thread_.joinable()) thread_.join();
    if (failure_) std::rethrow_exception(std::exchange(failure_, nullptr));
  }
  ~Background() {
    if (thread_.joinable()) thread_.join();
  }

 private:
  std::thread thread_;
  std::exception_ptr failure_;
};

// range_map.{csv,npy}, confidence_map.{csv,npy} (where the sensor's validity rule measures one),
// points.{csv,npy} (where the sensor has points), frames.csv, range_map.png and range_error.png;
// returns the plot's warning ("" when none). With more than one thread (--threads) the points,
// the largest file, are made and written beside the others.
std::string write_files(const SimulateOptions& opt, OutputDir& out, const systemc::SimulationResult& r, int threads) {
  const systemc::RangeMap& m = r.range_map;
  const std::size_t columns = m.column_names.size();
  // Named first, in the order the run lists them.
  const bool map_npy = as_npy(opt, m.range_m.size() * columns);
  const std::string map_path = out.staged(map_npy ? "range_map.npy" : "range_map.csv");
  const bool conf_npy = as_npy(opt, m.confidence.size() * columns);
  const std::string conf_path =
      m.confidence.empty() ? "" : out.staged(conf_npy ? "confidence_map.npy" : "confidence_map.csv");
  Background points;
  if (!r.points.empty()) {
    const bool npy = as_npy(opt, r.points.values());
    auto job = [npy, path = out.staged(npy ? "points.npy" : "points.csv"), &r] {
      if (npy)
        write_npy_table(path, r.points);
      else
        write_file(path, systemc::table_csv(r.points));
    };
    if (threads > 1)
      points.start(job);
    else
      job();
  }
  if (map_npy)
    write_npy_matrix(map_path, m.range_m, columns);
  else
    write_file(map_path, systemc::range_map_csv(m));
  if (!conf_path.empty()) {
    if (conf_npy)
      write_npy_matrix(conf_path, m.confidence, columns);
    else
      write_file(conf_path, systemc::confidence_map_csv(m));
  }
  out.write("frames.csv", r.frames_csv);
  const std::string warning = opt.no_plots ? "" : render_range_map(out, m);
  points.join();
  return warning;
}

// summary.json (with any warnings), the trace, the commit, then the JSON (--json) or the summary
// and the files written.
int finish(const SimulateOptions& opt, OutputDir& out, TraceOutput& trace, nlohmann::json& j,
           const std::string& plot_warning, const systemc::SimulationReport& report) {
  if (!plot_warning.empty()) j["warnings"] = {plot_warning};
  if (trace.enabled()) j["trace"] = opt.trace;
  out.write("summary.json", j.dump(2) + "\n");
  trace.finish();  // may throw: the output folder is still staged
  const std::vector<std::string> written = out.commit();
  const std::string trace_file = trace.commit();
  if (opt.json) {
    fmt::print("{}\n", j.dump(2));
    return kExitOk;
  }
  if (!plot_warning.empty()) fmt::print(stderr, "rangesim: warning: {}\n", plot_warning);
  print_summary(report);
  for (const auto& w : written) fmt::print("  wrote {}\n", w);
  if (!trace_file.empty()) fmt::print("  wrote {}\n", trace_file);
  return kExitOk;
}

}  // namespace

int run_and_render(const SimulateOptions& opt, const ParamSet& params, const SimulateEntry& entry) {
  CommandHost host(opt);
  systemc::SimulationResult r = entry.run(simulation_request(opt), params, host);
  const auto t0 = Progress::Clock::now();
  const double c0 = cpu_with_children_s();
  const std::string warning = write_files(opt, host.out(), r, simulation_request(opt).threads);
  // What the outputs cost (files and plot, gnuplot's CPU included), for `bench`'s output_share.
  r.summary["output_wall_time_s"] = std::chrono::duration<double>(Progress::Clock::now() - t0).count();
  r.summary["output_cpu_s"] = cpu_with_children_s() - c0;
  return finish(opt, host.out(), host.trace(), r.summary, warning, r.report);
}

}  // namespace rangesim::app
