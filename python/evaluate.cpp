// Sensor.evaluate(): `rangesim evaluate` returning data. The preset's grid (or the signal and
// background given) through the sensor's golden model, and with `trials` the Monte Carlo sweep of
// its clock-level kernels: the same library calls as the command (app/evaluate_params.h,
// app/montecarlo/mc_evaluate.h), so `summary` is the command's summary.json.
#include <pybind11/stl.h>

#include <cmath>
#include <fmt/format.h>
#include <memory>

#include "app/cli_common.h"
#include "app/evaluate_params.h"
#include "app/evaluation_output.h"
#include "app/montecarlo/mc_evaluate.h"
#include "golden/common/evaluate_sensor.h"
#include "golden/common/grid_axes.h"
#include "python/bindings.h"
#include "systemc/common/montecarlo.h"

namespace rangesim::python {

namespace {

// A grid axis: a "LO:HI:N" string as on the command line, or any ascending values. The values go
// to the models through golden::GridAxesScope; their ends and count become the preset's
// `evaluation.*` keys, so the command's checks of the range apply to them unchanged.
struct AxisArg {
  std::optional<std::string> text;  // "LO:HI:N" for the preset (nullopt: the preset's own grid)
  std::vector<double> values;       // the explicit values (empty: log-spaced from `text`)
};

AxisArg grid_arg(const py::object& values, const std::string& axis) {
  if (values.is_none()) return {};
  if (py::isinstance<py::str>(values)) return {values.cast<std::string>(), {}};
  const std::string allowed =
      "allowed: a 1-D array of ascending values > 0 (any spacing, 1 <= n <= 10000), or \"LO:HI:N\" (log-spaced)";
  // Null (the Python error cleared) when `values` is not convertible to numbers.
  const auto a = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(values);
  if (!a || a.ndim() != 1 || a.size() == 0 || a.size() > 10000)
    bad_argument(axis, fmt::format("{}: {}", axis, allowed));
  const auto v = a.unchecked<1>();
  AxisArg r;
  for (py::ssize_t k = 0; k < a.size(); ++k) r.values.push_back(v(k));
  const double lo = r.values.front(), hi = r.values.back();
  r.text = fmt::format("{}:{}:{}", lo, hi, r.values.size());  // reads back exactly
  // Ends the command would refuse are left to its own check (the same message); between
  // acceptable ends every value must be finite and above the one before it.
  if (std::isfinite(lo) && std::isfinite(hi) && lo > 0 && lo <= hi)
    for (std::size_t k = 1; k < r.values.size(); ++k)
      if (!(r.values[k] > r.values[k - 1]) || !std::isfinite(r.values[k]))
        bad_argument(axis, fmt::format("{}: value [{}] = {:g} is not above the one before it ({:g}); {}", axis, k,
                                       r.values[k], r.values[k - 1], allowed));
  return r;
}

py::dict axis_fields(const golden::EvalResult& ev) {
  py::dict f;
  f["sensor"] = ev.sensor;
  f["signal"] = vector_array(ev.signal.values);
  f["background"] = vector_array(ev.background.values);
  f["signal_unit"] = ev.signal.unit;
  f["background_unit"] = ev.background.unit;
  return f;
}

// The golden grid as arrays (rows background, columns signal, as the command's CSV matrices).
py::dict golden_fields(const golden::EvalResult& ev) {
  py::dict f = axis_fields(ev);
  const std::size_t nb = ev.background.values.size(), ns = ev.signal.values.size();
  // Reason ids in the model's legend order ("detectable" first); an id outside it is appended.
  std::vector<std::pair<std::string, std::string>> reasons = ev.reasons;
  const auto code_of = [&reasons](const std::string& id) {
    for (std::size_t i = 0; i < reasons.size(); ++i)
      if (reasons[i].first == id) return static_cast<int>(i);
    reasons.emplace_back(id, "");
    return static_cast<int>(reasons.size() - 1);
  };
  py::array_t<int> detect({nb, ns});
  py::array_t<bool> detectable({nb, ns});
  auto d = detect.mutable_unchecked<2>();
  auto ok = detectable.mutable_unchecked<2>();
  for (std::size_t ib = 0; ib < nb; ++ib)
    for (std::size_t is = 0; is < ns; ++is) {
      d(ib, is) = code_of(ev.at(ib, is).detect);
      ok(ib, is) = ev.at(ib, is).detect == "detectable";
    }
  f["detect"] = detect;
  f["detectable"] = detectable;
  py::list reason_list;
  for (const auto& [id, text] : reasons) reason_list.append(py::make_tuple(id, text));
  f["reasons"] = reason_list;
  f["accuracy_m"] = grid_array(nb, ns, [&](std::size_t b, std::size_t s) { return ev.at(b, s).accuracy_m; });
  f["sbr_total_dB"] = grid_array(nb, ns, [&](std::size_t b, std::size_t s) { return ev.at(b, s).sbr_total_dB; });
  f["sbr_ratio_dB"] = grid_array(nb, ns, [&](std::size_t b, std::size_t s) { return ev.at(b, s).sbr_ratio_dB; });
  py::dict metrics;
  for (std::size_t k = 0; k < ev.metric_names.size(); ++k)
    metrics[py::str(ev.metric_names[k])] = grid_array(nb, ns, [&](std::size_t b, std::size_t s) {
      const auto& m = ev.at(b, s).metrics;
      return k < m.size() ? m[k] : golden::kNaN;
    });
  f["metrics"] = metrics;
  py::dict sweeps;
  for (const auto& sw : ev.sweeps) {
    py::list series;
    for (const auto& c : sw.series)
      series.append(make_result(
          py::dict(py::arg("label") = c.label, py::arg("x") = vector_array(c.x), py::arg("y") = vector_array(c.y))));
    sweeps[py::str(sw.id)] = make_result(py::dict(py::arg("title") = sw.title, py::arg("x_label") = sw.x_label,
                                                  py::arg("x_unit") = sw.x_unit, py::arg("y_label") = sw.y_label,
                                                  py::arg("y_unit") = sw.y_unit, py::arg("log_x") = sw.log_x,
                                                  py::arg("log_y") = sw.log_y, py::arg("series") = series));
  }
  f["sweeps"] = sweeps;
  return f;
}

// The Monte Carlo statistics as arrays in metres (NaN, and 0 trials, where no trials ran: points
// not detectable by the golden model), as the command's mc_points.csv has them.
py::object monte_carlo_fields(const app::mc::McGrid& g) {
  const golden::EvalResult& ev = *g.ev;
  const std::size_t nb = ev.background.values.size(), ns = ev.signal.values.size();
  py::dict f;
  py::array_t<long long> trials({nb, ns}), detected({nb, ns});
  auto t = trials.mutable_unchecked<2>();
  auto d = detected.mutable_unchecked<2>();
  for (std::size_t b = 0; b < nb; ++b)
    for (std::size_t s = 0; s < ns; ++s) {
      const auto& st = g.stats[b * ns + s];
      t(b, s) = st ? st->trials : 0;
      d(b, s) = st ? st->detected : 0;
    }
  f["trials"] = trials;
  f["detected"] = detected;
  using Interval = app::mc::McInterval app::mc::McPointStats::*;
  const auto interval = [&](const char* name, Interval member, double scale) {
    const auto part = [&](double app::mc::McInterval::*end) {
      return grid_array(nb, ns, [&](std::size_t b, std::size_t s) {
        const auto& st = g.stats[b * ns + s];
        return st ? ((*st).*member.*end) * scale : golden::kNaN;
      });
    };
    const std::string n = name, unit = n.rfind("p_", 0) == 0 ? "" : "_m";
    f[py::str(n + unit)] = part(&app::mc::McInterval::value);
    f[py::str(n + "_lo" + unit)] = part(&app::mc::McInterval::lo);
    f[py::str(n + "_hi" + unit)] = part(&app::mc::McInterval::hi);
  };
  interval("p_detect", &app::mc::McPointStats::p_detect, 1.0);
  interval("bias", &app::mc::McPointStats::bias, g.metres_per_unit);
  interval("std", &app::mc::McPointStats::std, g.metres_per_unit);
  interval("accuracy", &app::mc::McPointStats::rms, g.metres_per_unit);
  interval("p_outlier", &app::mc::McPointStats::p_outlier, 1.0);
  interval("accuracy_clean", &app::mc::McPointStats::rms_clean, g.metres_per_unit);
  return make_result(f);
}

// The command's warning for points that ran out of trials, as a Python warning.
void warn_capped(const app::mc::McSweepResult& r, const app::mc::McSweepOptions& o, std::size_t points) {
  if (r.points_capped == 0) return;
  const std::string text = fmt::format(
      "rangesim evaluate: {} of {} points reached max_trials {} before the 95% CI half-width of the accuracy fell to "
      "target_error {:g} m (largest left: {:.3g} m); raise max_trials for them",
      r.points_capped, points, o.max_trials, o.target_error_m, r.worst_capped_half_width_m);
  if (PyErr_WarnEx(PyExc_RuntimeWarning, text.c_str(), 1) != 0) throw py::error_already_set();
}

void mc_progress(long long, long long, long long, double, double) {
  if (Interruption* in = Interruption::current(); in && in->poll()) in->raise_stop();
}

py::object evaluate(const Sensor& sensor, const py::object& signal, const py::object& background,
                    std::optional<long long> trials, unsigned long long seed, std::optional<int> samplings,
                    std::optional<int> adc_bits, std::optional<int> frames, std::optional<double> target_error,
                    std::optional<long long> max_trials, std::optional<int> threads) {
  // Everything is checked before anything runs, in the command's order and with its messages.
  ParamSet params = sensor.params;
  app::require_modelled(params, "evaluate");
  app::EvaluateOptions opt;
  const AxisArg signal_axis = grid_arg(signal, "signal"), background_axis = grid_arg(background, "background");
  opt.signal = signal_axis.text;
  opt.background = background_axis.text;
  opt.samplings = samplings;
  opt.adc_bits = adc_bits;
  opt.frames = frames;
  opt.trials = trials;
  opt.target_error = target_error;
  opt.max_trials = max_trials;
  opt.threads = threads;
  opt.seed = seed;
  app::apply_evaluate_flags(params, opt);
  const bool monte_carlo = trials || target_error;
  std::unique_ptr<app::mc::McSweepOptions> sopt;
  std::unique_ptr<mc::McModel> model;
  if (monte_carlo) {
    sopt = std::make_unique<app::mc::McSweepOptions>(app::mc::sweep_options(opt));
    model = mc::make_mc_model(params);
  }

  const golden::EvalResult ev = without_gil([&](Interruption&) {
    const golden::GridAxesScope axes(signal_axis.values, background_axis.values);
    return golden::evaluate_sensor(params, &check_interrupt_progress);
  });
  py::dict fields = golden_fields(ev);
  nlohmann::json summary = app::summary_json(ev, params);
  fields["monte_carlo"] = py::none();
  if (monte_carlo) {
    auto points = std::make_unique<std::vector<app::mc::McSweepPoint>>(app::mc::detectable_points(ev));
    const app::mc::McSweepResult r = without_gil([&](Interruption& in) {
      sopt->stop = in.stop_flag();
      sopt->progress = &mc_progress;
      sopt->progress_interval_s = 0.1;  // how often Ctrl-C is looked for
      app::mc::McSweepResult res = app::mc::run_mc_sweep(*model, *points, *sopt, nullptr);
      if (!res.complete) {
        // Workers that did not stop within the grace time still use the model, the points and
        // the options: they are left to them (the command ends the process instead).
        if (res.abandoned) (void)model.release(), (void)points.release(), (void)sopt.release();
        throw Interrupted();
      }
      return res;
    });
    const app::mc::McGrid grid = app::mc::make_grid(ev, *points, r, *model, *sopt);
    summary["monte_carlo"] = app::mc::mc_summary_json(grid);
    fields["monte_carlo"] = monte_carlo_fields(grid);
    warn_capped(r, *sopt, points->size());
  }
  fields["summary"] = to_python(summary);
  return make_result(fields);
}

}  // namespace

void bind_evaluate(SensorClass& sensor) {
  sensor.def("evaluate", &evaluate, py::arg("signal") = py::none(), py::arg("background") = py::none(),
             py::arg("trials") = py::none(), py::arg("seed") = 1, py::kw_only(), py::arg("samplings") = py::none(),
             py::arg("adc_bits") = py::none(), py::arg("frames") = py::none(), py::arg("target_error") = py::none(),
             py::arg("max_trials") = py::none(), py::arg("threads") = py::none(),
             R"(`rangesim evaluate` as data. signal, background: the grid axes in the sensor's unit (V, A or Hz),
any ascending values > 0 (e.g. numpy.linspace or numpy.geomspace; up to 10000) or "LO:HI:N" (log-spaced
as on the command line); default the preset's.
trials (or target_error): also the Monte Carlo sweep of the clock-level kernels at every detectable point
(seed, max_trials, threads as --seed, --max-trials, --threads). samplings, adc_bits, frames: as the flags.

Returns a namespace: signal, background (1-D), signal_unit, background_unit; 2-D arrays (rows background,
columns signal) detect (codes into reasons, a list of (id, description), 0 = detectable), detectable,
accuracy_m, sbr_total_dB (eq. 3.11), sbr_ratio_dB (eq. 3.23/4.11), metrics {name: array}; sweeps
{id: namespace}; summary (the command's summary.json); monte_carlo (None, or arrays trials, detected,
p_detect[_lo|_hi], bias[_lo|_hi]_m, std[_lo|_hi]_m, accuracy[_lo|_hi]_m with 95% CIs).
Releases the GIL; Ctrl-C stops it (KeyboardInterrupt).)");
}

}  // namespace rangesim::python
