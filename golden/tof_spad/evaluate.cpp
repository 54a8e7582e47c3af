// The grid evaluation of tof-spad as a sensor-independent EvalResult: detectable area, SBR' both
// ways, accuracy at evaluation.distance_m, exact range edges, and the sweeps the issue asks for.
#include "golden/common/grid_axes.h"
#include "golden/tof_spad/evaluate.h"

#include <atomic>
#include <cmath>

#include "golden/common/grid_scan.h"
#include "golden/tof_spad/point_model.h"
#include "golden/tof_spad/ranges.h"
#include "golden/tof_spad/model.h"

namespace rangesim::golden {

namespace spad {

namespace {

EvalPoint to_point(const PointResult& p, double signal_Hz, double background_Hz) {
  EvalPoint q;
  q.signal = signal_Hz;
  q.background = background_Hz;
  q.detect = p.detect;
  q.sbr_total_dB = 20 * std::log10((signal_Hz + background_Hz) / background_Hz);
  q.sbr_ratio_dB = 20 * std::log10(signal_Hz / background_Hz);
  const bool ok = p.detect == "detectable";
  q.accuracy_m = ok ? p.accuracy_m : kNaN;
  const bool has_moments = p.moments.defined;
  q.metrics = {has_moments ? p.bias_m : kNaN, has_moments ? p.std_m : kNaN, p.signal_counts,
               p.background_counts,           p.detections_per_cycle,       p.armed_at_echo};
  return q;
}

// Accuracy against the background at a fixed signal, for three estimators (issue: with and
// without Coates correction).
EvalSweep coates_sweep(const SpadModel& m, const std::vector<double>& background_Hz) {
  const auto& e = m.config().evaluation;
  const int pw = m.config().histogram.peak_window_bins;
  EvalSweep sw{"accuracy_vs_background_coates",
               "tof-spad: accuracy against background at " + std::to_string(static_cast<long>(e.sweep_signal_Hz)) +
                   " counts/s signal, with and without Coates correction",
               "background count rate",
               "Hz",
               "rms range error",
               "m",
               true,
               true,
               {}};
  const std::vector<std::pair<std::string, EstimatorConfig>> variants = {
      {"Coates + background subtraction", {pw, true, true}},
      {"background subtraction, no Coates", {pw, false, true}},
      {"plain centroid (thesis eq. 4.19)", {pw, false, false}}};
  for (const auto& [label, est] : variants) {
    EvalSeries s{label, {}, {}};
    for (double b : background_Hz) {
      const PointResult p = m.evaluate(e.sweep_signal_Hz, b, e.distance_m, est);
      s.x.push_back(b);
      s.y.push_back(p.detect == "detectable" ? p.accuracy_m : kNaN);
    }
    sw.series.push_back(std::move(s));
  }
  return sw;
}

// Bias, spread and rms error across the distance range at the reference conditions.
EvalSweep distance_sweep(const SpadModel& m) {
  const auto& e = m.config().evaluation;
  EvalSweep sw{"accuracy_vs_distance",
               "tof-spad: range error against distance at " + std::to_string(static_cast<long>(e.reference_signal_Hz)) +
                   " counts/s signal, " + std::to_string(static_cast<long>(e.reference_background_Hz)) +
                   " counts/s background",
               "distance",
               "m",
               "range error",
               "m",
               false,
               false,
               {}};
  const Nonlinearity n = nonlinearity(m, e.reference_signal_Hz, e.reference_background_Hz,
                                      linear_spaced(e.distance_min_m, e.distance_max_m, e.distance_points));
  EvalSeries rms{"rms error", n.distance_m, {}}, bias{"bias (TDC nonlinearity)", n.distance_m, n.bias_m},
      sd{"standard deviation", n.distance_m, n.std_m};
  for (size_t i = 0; i < n.bias_m.size(); ++i) rms.y.push_back(std::hypot(n.bias_m[i], n.std_m[i]));
  sw.series = {std::move(rms), std::move(bias), std::move(sd)};
  return sw;
}

}  // namespace

EvalResult evaluate_grid(const TofSpadConfig& cfg, ProgressFn progress, EvalSink* sink) {
  const SpadModel model(cfg);
  const auto& e = cfg.evaluation;
  EvalResult r;
  r.sensor = "tof-spad";
  r.signal = {"signal", "Hz",
              grid_axis(GridAxis::Signal, log_spaced(e.signal_min_Hz, e.signal_max_Hz, e.signal_points))};
  r.background = {
      "background", "Hz",
      grid_axis(GridAxis::Background, log_spaced(e.background_min_Hz, e.background_max_Hz, e.background_points))};
  r.reasons = SpadModel::reasons();
  r.metric_names = metric_names();
  const auto& sig = r.signal.values;
  const auto& bg = r.background.values;
  std::atomic<int> not_converged{0};
  const auto point = [&](size_t ib, size_t is) {
    const PointResult p = model.evaluate(sig[is], bg[ib], e.distance_m);
    not_converged += !p.chain_converged;
    return to_point(p, sig[is], bg[ib]);
  };
  // SpadModel::evaluate is const and keeps no state: the rows can share the cores.
  const GridScan g = scan_grid(r, point, progress, sink, true);
  r.distance_m = e.distance_m;

  auto detectable = [&](double s, double b) { return model.evaluate(s, b, e.distance_m).detect == "detectable"; };
  r.signal_range = detectable_range(
      sig, g.first_row_detectable, [&](double s) { return detectable(s, bg.front()); }, bg.front());
  r.background_range = detectable_range(
      bg, g.last_column_detectable, [&](double b) { return detectable(sig.back(), b); }, sig.back());

  const PointResult ref = model.evaluate(e.reference_signal_Hz, e.reference_background_Hz, e.distance_m);
  r.summary_extra = {{"tdc_lsb_s", model.bins().lsb_s},
                     {"tdc_codes_per_period", model.bins().codes},
                     {"irf_sigma_s", irf_sigma_s(cfg)},
                     {"cycles", model.cycles()},
                     {"tdc_share", model.share()},
                     {"dead_time_limit_Hz", 1.0 / cfg.spad.dead_time_s},
                     {"afterpulse_armed_fraction_max", afterpulse_armed_fraction(cfg)},
                     {"reference_accuracy_m", ref.accuracy_m},
                     {"reference_std_m", ref.std_m},
                     {"chain_not_converged_points", not_converged.load()}};
  r.sweeps.push_back(coates_sweep(model, bg));
  r.sweeps.push_back(distance_sweep(model));
  return r;
}

}  // namespace spad

EvalResult evaluate_tof_spad(const ParamSet& params, ProgressFn progress) {
  EvalResult r = spad::evaluate_grid(tof_spad_from_params(params), progress);
  r.sensor = params.sensor_id();
  return r;
}

EvalResult evaluate_tof_spad_streamed(const ParamSet& params, ProgressFn progress, EvalSink& sink) {
  EvalResult r = spad::evaluate_grid(tof_spad_from_params(params), progress, &sink);
  r.sensor = params.sensor_id();
  return r;
}

std::vector<PublishedFigure> published_figures_tof_spad(const ParamSet& params) {
  return spad::published_figures(tof_spad_from_params(params));
}

}  // namespace rangesim::golden
