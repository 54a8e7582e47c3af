#include "app/simulate/simulate_render.h"

#include <fmt/format.h>

#include <memory>
#include <optional>
#include <stdexcept>

#include "app/cli_common.h"
#include "app/output_dir.h"
#include "app/resource_estimate.h"
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
  r.trace_rows = opt.trace_rows;
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

// range_map.csv, confidence_map.csv (where the sensor's validity rule measures one), points.csv
// (where the sensor has points), frames.csv, range_map.png and range_error.png; returns the plot's warning ("" when
// none).
std::string write_files(const SimulateOptions& opt, OutputDir& out, const systemc::SimulationResult& r) {
  const systemc::RangeMap& m = r.range_map;
  out.write("range_map.csv", systemc::range_map_csv(m));
  if (!m.confidence.empty()) out.write("confidence_map.csv", systemc::confidence_map_csv(m));
  if (!r.points_csv.empty()) out.write("points.csv", r.points_csv);
  out.write("frames.csv", r.frames_csv);
  if (opt.no_plots) return "";
  return render_range_map(out, m);
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
  const std::string warning = write_files(opt, host.out(), r);
  return finish(opt, host.out(), host.trace(), r.summary, warning, r.report);
}

}  // namespace rangesim::app
