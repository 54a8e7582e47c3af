#include "app/simulate/simulate_render.h"

#include <fmt/format.h>

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <functional>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "app/cli_common.h"
#include "app/matrix_rows.h"
#include "app/output_dir.h"
#include "app/resource_estimate.h"
#include "app/simulate/npy_writer.h"
#include "app/simulate/png_writer.h"
#include "app/simulate/run_jobs.h"
#include "app/simulate/simulate_output.h"
#include "app/simulate/simulate_report.h"
#include "app/simulate/trace_output.h"
#include "systemc/common/simulation.h"

namespace rangesim::app {

namespace {

// --threads, or every core.
int run_threads(const SimulateOptions& opt) {
  return opt.threads.value_or(static_cast<int>(std::max(1u, std::thread::hardware_concurrency())));
}

}  // namespace

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
  r.threads = run_threads(opt);
  r.trace_rows = opt.trace_rows;
  r.trace_pixels = opt.trace_pixels;
  r.points = opt.points;
  return r;
}

namespace {

// A table of `values` numbers goes out as .npy (true) or CSV.
bool as_npy(const SimulateOptions& opt, std::size_t values) { return opt.npy || (!opt.csv && values > kNpyMinValues); }

// A matrix file staged now as NAME.npy or NAME.csv (as_npy), written by the job. The .npy job reads
// the rows only (it may run while the map moves on); the CSV job whatever `csv` reads.
std::function<void()> matrix_job(const SimulateOptions& opt, OutputDir& out, const std::string& name, MatrixRows rows,
                                 std::size_t columns, std::function<std::string()> csv) {
  const bool npy = as_npy(opt, rows.size() * columns);
  return [npy, path = out.staged(name + (npy ? ".npy" : ".csv")), rows, columns, csv = std::move(csv)] {
    if (npy)
      write_npy_matrix(path, rows, columns);
    else
      write_file(path, csv());
  };
}

// The map's own files: range_map.{npy,csv}, confidence_map.{npy,csv} (where the sensor's validity
// rule measures one) and range_map.png, staged now in that order; a job each, the image's first
// (the costliest).
std::vector<std::function<void()>> map_jobs(const SimulateOptions& opt, OutputDir& out, const systemc::RangeMap& m) {
  const std::size_t columns = m.column_names.size();
  std::vector<std::function<void()>> jobs;
  jobs.push_back(matrix_job(opt, out, "range_map", m.range_m, columns, [&m] { return systemc::range_map_csv(m); }));
  if (!m.confidence.empty())
    jobs.push_back(
        matrix_job(opt, out, "confidence_map", m.confidence, columns, [&m] { return systemc::confidence_map_csv(m); }));
  if (!opt.no_plots) jobs.insert(jobs.begin(), range_image_job(out, m));
  return jobs;
}

// The map's files written on another thread while the scene run goes on (map_ready, truth_ready).
// `host_slot` points to it while it lives: the host adds the truth's jobs through it.
class MapFiles : public systemc::MapWork {
 public:
  MapFiles(std::vector<std::function<void()>> jobs, MapFiles*& host_slot) : jobs(std::move(jobs)), slot_(host_slot) {
    slot_ = this;
  }
  ~MapFiles() override { slot_ = nullptr; }  // then `jobs` waits
  BackgroundJobs jobs;
  bool error_image = false;  // range_error.png is among them

 private:
  MapFiles*& slot_;
};

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
  // A map large enough for .npy (a full ls-conventional map's files and images took 3.4 to 4.2 ms of
  // CPU) begins going out at once, on the CPU the run leaves idle while it scores the map against
  // its truth (the helper's CPU, six runs); a small one, CSV, or one thread waits for write_files.
  std::unique_ptr<systemc::MapWork> map_ready(const systemc::RangeMap& m) override {
    if (!out_ || run_threads(opt_) < 2 || !as_npy(opt_, m.range_m.size() * m.column_names.size())) return nullptr;
    return std::make_unique<MapFiles>(map_jobs(opt_, *out_, m), map_files_);
  }
  void truth_ready(const systemc::RangeMap& m) override {
    if (!map_files_ || opt_.no_plots) return;
    if (auto job = error_image_job(*out_, m)) {
      map_files_->jobs.add(std::move(job));
      map_files_->error_image = true;
    }
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
  MapFiles* map_files_ = nullptr;      // what map_ready began, while it lives
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

// What the scene run had handed on to be written already (map_ready), or null.
MapFiles* map_files(const systemc::SimulationResult& r) { return dynamic_cast<MapFiles*>(r.map_work.get()); }

// range_map.{csv,npy}, confidence_map.{csv,npy} (where the sensor's validity rule measures one),
// range_map.png and range_error.png, unless the run began them (map_ready, truth_ready);
// points.{csv,npy} (with --points, where the sensor has points), frames.csv and summary.json: staged
// in that order (the order the run lists them), each written by a job. With more than one thread
// (--threads) the jobs run side by side, the costliest first: the points (9.6 MB for a full
// ls-conventional map), the images (drawing and deflate, about 1 ms each), then the maps (1.1 MB
// each); where the run began the map's files, on its helper and the caller. summary.json is
// complete but for the output's own times, which include its writing. Returns when every job has
// ended, rethrowing the first failure.
void write_files(const SimulateOptions& opt, OutputDir& out, const systemc::SimulationResult& r, int threads) {
  const systemc::RangeMap& m = r.range_map;
  MapFiles* const begun = map_files(r);
  std::vector<std::function<void()>> maps = begun ? std::vector<std::function<void()>>{} : map_jobs(opt, out, m);
  std::function<void()> error;
  if (!opt.no_plots && !(begun && begun->error_image)) error = error_image_job(out, m);
  std::vector<std::function<void()>> jobs;  // the costliest first
  if (opt.points && !r.points.empty()) {
    const bool npy = as_npy(opt, r.points.values());
    jobs.emplace_back([npy, path = out.staged(npy ? "points.npy" : "points.csv"), &r] {
      if (npy)
        write_npy_table(path, r.points);
      else
        write_file(path, systemc::table_csv(r.points));
    });
  }
  if (error) jobs.push_back(std::move(error));
  for (auto& map : maps) jobs.push_back(std::move(map));
  jobs.emplace_back([path = out.staged("frames.csv"), &r] { write_file(path, r.frames_csv); });
  jobs.emplace_back([path = out.staged("summary.json"), &r] { write_file(path, r.summary.dump(2) + "\n"); });
  if (begun) {  // its helper takes them too: no thread to start
    for (auto& job : jobs) begun->jobs.add(std::move(job));
    begun->jobs.wait();
  } else {
    run_jobs(jobs, threads);
  }
}

// The files (write_files), the trace, then the commit; returns the paths written.
std::vector<std::string> write_and_commit(const SimulateOptions& opt, OutputDir& out, TraceOutput& trace,
                                          systemc::SimulationResult& r) {
  if (trace.enabled()) r.summary["trace"] = opt.trace;
  write_files(opt, out, r, run_threads(opt));
  trace.finish();  // may throw: the output folder is still staged
  std::vector<std::string> written = out.commit();
  const std::string trace_file = trace.commit();
  if (!trace_file.empty()) written.push_back(trace_file);
  return written;
}

// The JSON (--json), or the summary and the files written.
int report(const SimulateOptions& opt, const systemc::SimulationResult& r, const std::vector<std::string>& written) {
  if (opt.json) {
    fmt::print("{}\n", r.summary.dump(2));
    return kExitOk;
  }
  print_summary(r.report);
  for (const auto& w : written) fmt::print("  wrote {}\n", w);
  if (!opt.points && !r.points.empty()) fmt::print("  (per-point table not written: add --points)\n");
  return kExitOk;
}

}  // namespace

int run_and_render(const SimulateOptions& opt, const ParamSet& params, const SimulateEntry& entry) {
  CommandHost host(opt);
  systemc::SimulationResult r = entry.run(simulation_request(opt), params, host);
  const auto t0 = Progress::Clock::now();
  const double c0 = cpu_with_children_s();
  // The CPU the map's files took while the run went on (map_ready), counted with the output's.
  const double before = map_files(r) ? map_files(r)->jobs.cpu_s() : 0.0;
  const std::vector<std::string> written = write_and_commit(opt, host.out(), host.trace(), r);
  // What writing the files, drawing the images and committing the folder cost (every thread's
  // CPU), for `bench`'s output_share: in --json only, as summary.json is written before they end.
  // The wall time counts from the run's end: what the map's files took before it ran beside the run.
  r.summary["output_wall_time_s"] = std::chrono::duration<double>(Progress::Clock::now() - t0).count();
  r.summary["output_cpu_s"] = cpu_with_children_s() - c0 + before;
  r.summary["output_cpu_during_run_s"] = before;  // 0 where the helper had not run yet
  r.summary["output_begun_during_run"] = map_files(r) != nullptr;
  return report(opt, r, written);
}

}  // namespace rangesim::app
