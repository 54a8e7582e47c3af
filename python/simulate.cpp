// Sensor.simulate(): `rangesim simulate` returning data. The sensor's scene run from the
// simulate registry (app/cmd_simulate.h) with the same flag checks; the module is its host in
// place of the command's output folder and trace: nothing is written.
#include <pybind11/stl.h>

#include <cmath>
#include <fmt/format.h>

#include "app/resource_estimate.h"
#include "app/cmd_simulate.h"
#include "app/simulate/simulate_render.h"
#include "python/bindings.h"
#include "systemc/common/simulation.h"

namespace rangesim::python {

namespace {

// No files, no trace; progress is where Ctrl-C is looked for, except inside SystemC, whose
// processes must not be unwound by an exception from a hook.
class PythonHost : public systemc::SimulationHost {
 public:
  PythonHost(Interruption& in, bool interruptible) : in_(in), interruptible_(interruptible) {}
  std::string open_trace() override { return ""; }
  void open_output(const std::string&) override {}
  std::function<void(long long)> progress(const std::string&, long long) override {
    if (!interruptible_) return {};
    return [this](long long) { in_.check(); };
  }
  void check_memory(double bytes, const std::string& what, const std::string& reduce) override {
    app::check_resources("simulate", {app::kBaseMemoryBytes + bytes, 0, what, reduce}, "");
  }

 private:
  Interruption& in_;
  bool interruptible_;
};

py::object simulate(const Sensor& sensor, const py::object& scene, std::optional<long long> frames, std::uint64_t seed,
                    bool use_systemc, bool tick, bool noise_free, bool dense, bool no_aggregate, double time_step) {
  app::SimulateOptions opt;
  opt.scene = py::str(scene).cast<std::string>();  // str or os.PathLike
  opt.frames = frames;
  opt.seed = seed;
  opt.kernel_only = !use_systemc;
  opt.tick = tick;
  opt.noise_free = noise_free;
  opt.dense = dense;
  opt.no_aggregate = no_aggregate;
  opt.time_step_s = time_step;
  opt.no_plots = true;
  opt.points = true;  // points_csv is part of the result
  const app::SimulateEntry& entry = app::simulate_entry_for(sensor.params, opt);
  if (use_systemc) {
    // SystemC allows one elaboration per process (its simulation context cannot be reset).
    static bool elaborated = false;
    if (elaborated)
      bad_argument("systemc",
                   "systemc=True: SystemC elaborates once per process and this process has done so; allowed: "
                   "systemc=False (the bare clock kernels), or a new process");
    elaborated = true;
    app::route_systemc_reports_to_stderr();
  }
  const systemc::SimulationRequest request = app::simulation_request(opt);
  const systemc::SimulationResult r = without_gil([&](Interruption& in) {
    PythonHost host(in, !use_systemc);
    return entry.run(request, sensor.params, host);
  });

  const systemc::RangeMap& m = r.range_map;
  const std::size_t rows = m.range_m.size(), columns = rows ? m.range_m.front().size() : 0;
  const auto truth = [&m](std::size_t row, std::size_t c) {
    return row < m.truth_m.size() && c < m.truth_m[row].size() ? m.truth_m[row][c] : NAN;
  };
  py::array_t<bool> valid({rows, columns});
  auto v = valid.mutable_unchecked<2>();
  for (std::size_t row = 0; row < rows; ++row)
    for (std::size_t c = 0; c < columns; ++c) v(row, c) = m.valid(row, c);
  py::dict f;
  f["sensor"] = sensor.params.sensor_id();
  f["range_m"] = grid_array(rows, columns, [&m](std::size_t row, std::size_t c) { return m.range_m[row][c]; });
  f["valid"] = valid;
  f["truth_m"] = grid_array(rows, columns, truth);
  f["error_m"] = grid_array(rows, columns, [&](std::size_t row, std::size_t c) {
    return m.valid(row, c) ? m.range_m[row][c] - truth(row, c) : NAN;  // NaN too where there is no truth
  });
  f["confidence"] = grid_array(rows, columns, [&m](std::size_t row, std::size_t c) {
    return row < m.confidence.size() && c < m.confidence[row].size() ? m.confidence[row][c] : NAN;
  });
  f["confidence_label"] = m.confidence_label;
  f["validity_rule"] = m.validity_rule;
  f["first_row"] = m.first_row;
  f["column_names"] = m.column_names;
  f["title"] = m.title;
  f["x_label"] = m.x_label;
  f["y_label"] = m.y_label;
  f["points_csv"] = r.points.empty() ? std::string() : systemc::table_csv(r.points);
  f["frames_csv"] = r.frames_csv;
  f["summary"] = to_python(r.summary);
  return make_result(f);
}

}  // namespace

void bind_simulate(SensorClass& sensor) {
  sensor.def("simulate", &simulate, py::arg("scene"), py::arg("frames") = py::none(), py::arg("seed") = 1,
             py::kw_only(), py::arg("systemc") = false, py::arg("tick") = false, py::arg("noise_free") = false,
             py::arg("dense") = false, py::arg("no_aggregate") = false, py::arg("time_step") = 0.0,
             R"(`rangesim simulate --kernel-only` as data: the clock-level model on a scene file (scenes/*.toml).
frames: as --frames (default the sensor's: one range map); seed: key of the noise streams;
systemc=True runs the SystemC modules instead of the bare kernels (once per process: SystemC cannot
elaborate twice); tick, noise_free, dense, no_aggregate, time_step: as --tick, --noise-free, --dense,
--no-aggregate, --time-step.

Returns a namespace: range_m (2-D, NaN where no valid range), valid, truth_m (the ground truth the range is
scored against, NaN where none), error_m = range_m - truth_m, confidence (what the validity rule tested,
in confidence_label's unit), validity_rule, first_row, column_names, title, x_label, y_label; points_csv and frames_csv (the command's points.csv and frames.csv); summary (its summary.json).
Releases the GIL; Ctrl-C stops a kernel run (KeyboardInterrupt).)");
}

}  // namespace rangesim::python
