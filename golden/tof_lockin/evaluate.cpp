// tof-lockin's evaluation over signal x background photocurrent (thesis 4.1.2, Fig. 4.4-4.6) as a
// sensor-independent EvalResult: per-point verdicts and accuracy (lockin_point.h), exact edges of
// the detectable ranges by bisection, SBR' both ways, sweeps and the frame schedule.
#include <cmath>

#include "core/tof_lockin/config.h"
#include "golden/common/grid_axes.h"
#include "golden/common/evaluate_sensor.h"
#include "golden/common/grid_scan.h"
#include "golden/tof_lockin/lockin_point.h"
#include "golden/tof_lockin/lockin_sweeps.h"
#include "golden/tof_lockin/pulse_timing.h"
#include "golden/tof_lockin/tap_charge.h"
#include "golden/tof_lockin/model.h"

namespace rangesim::golden {

namespace {

bool detectable(const TofLockinConfig& cfg, double sig_A, double bg_A) {
  return evaluate_point(cfg, sig_A, bg_A, cfg.eval.distance_m, cfg.eval.frames_averaged).detect ==
         LockinDetect::Detectable;
}

// Edge between a non-detectable value `out` and a detectable `in` on a log axis, to 1e-12 relative.
template <class Pred>
double bisect_edge(double out, double in, Pred det) {
  for (int i = 0; i < 200 && std::fabs(in / out - 1.0) > 1e-12; ++i) {
    const double mid = std::sqrt(in * out);
    (det(mid) ? in : out) = mid;
  }
  return in;
}

// Detectable interval along an axis whose grid verdicts are `ok` (the detectable set along one
// axis is an interval: threshold below, saturation above).
template <class Pred>
EvalRange axis_range(const std::vector<double>& v, const std::vector<bool>& ok, double at, Pred det) {
  EvalRange r;
  r.at = at;
  int first = -1, last = -1;
  for (int i = 0; i < static_cast<int>(v.size()); ++i)
    if (ok[i]) last = i, first = first < 0 ? i : first;
  if (first < 0) return r;
  r.lo_limited_by_grid = first == 0;
  r.hi_limited_by_grid = last == static_cast<int>(v.size()) - 1;
  r.lo = r.lo_limited_by_grid ? v[first] : bisect_edge(v[first - 1], v[first], det);
  r.hi = r.hi_limited_by_grid ? v[last] : bisect_edge(v[last + 1], v[last], det);
  r.range_dB = 20.0 * std::log10(r.hi / r.lo);
  return r;
}

// One readout of the whole array: conversion of both FDs of each row, then shifting the row out.
double readout_time_s(const TofLockinConfig& cfg) {
  return cfg.pixel.rows * static_cast<double>(cfg.readout.adc_conversion_cycles + cfg.readout.output_cycles_per_row) /
         cfg.readout.clock_Hz;
}

// The grid kept (sink == nullptr) or streamed; everything else is the same.
EvalResult evaluate_grid(const ParamSet& params, ProgressFn progress, EvalSink* sink) {
  const TofLockinConfig cfg = tof_lockin_from_params(params);
  const auto& e = cfg.eval;
  EvalResult r;
  r.sensor = params.sensor_id();
  r.signal = {"signal", "A", grid_axis(GridAxis::Signal, log_spaced(e.signal_min_A, e.signal_max_A, e.signal_points))};
  r.background = {
      "background", "A",
      grid_axis(GridAxis::Background, log_spaced(e.background_min_A, e.background_max_A, e.background_points))};
  r.reasons = {{"detectable", "range can be derived"},
               {"below_threshold", "light-induced V1 + V2 below readout.detection_threshold_V (V_sig_min of eq. 4.11)"},
               {"noise_limited", "SNR of V1 + V2 below readout.min_snr: the ratio of eq. 2.25 has no usable moments"},
               {"range_error_unbounded",
                "rms noise of one range value above readout.max_range_noise_fraction x c T0 / 2 (delta method)"},
               {"saturated", "a tap's FD swing exceeds V_sat or its ADC input the full scale"},
               {"out_of_range", "delay 2L/c outside [0, T0]: distance beyond c T0 / 2"}};
  r.metric_names = {"std_m", "bias_m", "v1_V", "v2_V", "signal_V", "n1_e", "n2_e", "snr", "std_first_order_m"};
  const auto& sig = r.signal.values;
  const auto& bg = r.background.values;
  const size_t n_metrics = r.metric_names.size();
  const auto point = [&](size_t ib, size_t is) {
    const LockinPoint p = evaluate_point(cfg, sig[is], bg[ib], e.distance_m, e.frames_averaged);
    EvalPoint q;
    q.signal = sig[is];
    q.background = bg[ib];
    q.detect = to_string(p.detect);
    // SBR' on photocurrents: signal V1 + V2 over the background of one tap integrate over the
    // same open time N T0, so the current ratio is the voltage ratio of eq. 3.11 / 4.11.
    q.sbr_total_dB = 20.0 * std::log10((sig[is] + bg[ib]) / bg[ib]);
    q.sbr_ratio_dB = 20.0 * std::log10(sig[is] / bg[ib]);
    const bool ok = p.detect == LockinDetect::Detectable;
    q.accuracy_m = ok ? p.accuracy_m : kNaN;
    q.metrics =
        ok ? std::vector<double>{p.std_m, p.bias_m, p.v1_V, p.v2_V, p.signal_V, p.n1_e, p.n2_e, p.snr, p.std_first_m}
           : std::vector<double>(n_metrics, kNaN);
    return q;
  };
  // evaluate_point is a function of its arguments alone: the rows can share the cores.
  const GridScan g = scan_grid(r, point, progress, sink, true);

  // Signal range at the lowest background, background range at the highest signal.
  r.signal_range =
      axis_range(sig, g.first_row_detectable, bg.front(), [&](double s) { return detectable(cfg, s, bg.front()); });
  r.background_range =
      axis_range(bg, g.last_column_detectable, sig.back(), [&](double b) { return detectable(cfg, sig.back(), b); });
  r.distance_m = e.distance_m;

  const double frame_s = cfg.gates.accumulations_per_frame * repetition_period_s(cfg.source) + readout_time_s(cfg);
  const double frames_per_image = cfg.readout.ambient_subtraction ? 2.0 : 1.0;
  r.summary_extra = {{"frames_averaged", static_cast<double>(e.frames_averaged)},
                     {"max_range_m", max_range_m(cfg.source)},
                     {"accumulation_time_s", cfg.gates.accumulations_per_frame * repetition_period_s(cfg.source)},
                     {"frame_time_s", frame_s},
                     {"frames_per_range_image", frames_per_image},
                     {"range_images_per_s", 1.0 / (frames_per_image * frame_s)},
                     {"adc_lsb_V", adc_lsb_V(cfg)},
                     {"ktc_noise_V", ktc_noise_V(cfg, 0)},
                     {"signal_V_at_signal_max", evaluate_point(cfg, sig.back(), 0.0, e.distance_m, 1).signal_V}};
  r.sweeps = lockin_sweeps(cfg, sig, bg);
  return r;
}

}  // namespace

EvalResult evaluate_tof_lockin(const ParamSet& params, ProgressFn progress) {
  return evaluate_grid(params, progress, nullptr);
}

EvalResult evaluate_tof_lockin_streamed(const ParamSet& params, ProgressFn progress, EvalSink& sink) {
  return evaluate_grid(params, progress, &sink);
}

}  // namespace rangesim::golden
