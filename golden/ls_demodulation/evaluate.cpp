// ls-demodulation's evaluation over the signal x background grid as an EvalResult, its sweeps
// (thesis Fig. 3.6, 3.8, 3.9, selectivity, step settling) and its published figures.
#include <cmath>

#include "core/ls_demodulation/config.h"
#include "golden/common/grid_axes.h"
#include "golden/common/evaluate_sensor.h"
#include "golden/common/grid_scan.h"
#include "golden/ls_demodulation/evaluation.h"
#include "golden/ls_demodulation/published.h"
#include "golden/ls_demodulation/selectivity.h"
#include "golden/ls_demodulation/model.h"

namespace rangesim::golden {

namespace {

EvalPoint to_eval_point(const DemodPoint& p, size_t n_metrics) {
  EvalPoint q;
  q.signal = p.signal_A;
  q.background = p.background_A;
  q.detect = to_string(p.detect);
  q.sbr_total_dB = p.sbr_total_dB;
  q.sbr_ratio_dB = p.sbr_ratio_dB;
  q.metrics.assign(n_metrics, kNaN);
  q.metrics[0] = p.peak_output_V;
  q.metrics[1] = p.background_output_V;
  q.metrics[2] = p.row_false_activation;
  if (p.detect == DemodDetect::Detectable) {
    const DemodAccuracy& a = p.accuracy;
    q.accuracy_m = a.accuracy_m;
    q.metrics[3] = a.accuracy_px;
    q.metrics[4] = a.bias_rms_px;
    q.metrics[5] = a.noise_std_px;
    q.metrics[6] = a.worst_error_px;
    q.metrics[7] = a.p_detect_min;
    q.metrics[8] = a.detected_fraction;
    q.metrics[9] = a.p_detect;
    q.metrics[10] = a.accuracy_clean_px;
    q.metrics[11] = a.p_outlier;
    q.p_detect = a.p_detect, q.p_outlier = a.p_outlier, q.accuracy_clean_m = a.accuracy_clean_m;
  }
  return q;
}

// The grid kept (sink == nullptr) or streamed; everything else is the same.
EvalResult evaluate_grid(const ParamSet& params, ProgressFn progress, EvalSink* sink) {
  const LsDemodulationConfig cfg = ls_demodulation_from_params(params);
  const auto& g = cfg.grid;
  EvalResult r;
  r.sensor = params.sensor_id();
  r.signal = {"signal", "A", grid_axis(GridAxis::Signal, log_spaced(g.signal_min_A, g.signal_max_A, g.signal_points))};
  r.background = {
      "background", "A",
      grid_axis(GridAxis::Background, log_spaced(g.background_min_A, g.background_max_A, g.background_points))};
  r.reasons = {{"detectable", "range can be derived"},
               {"below_threshold", "noise-free V_out+ - V_out- at the spot peak stays below V_cmp"},
               {"saturated", "an integrator swing exceeds V_sat (background alone or with the spot)"},
               {"background_activation",
                "background alone reaches V_cmp, or its noise activates more than "
                "comparator.false_activation_max of the rows"}};
  r.metric_names = {"peak_output_V",  "background_output_V", "row_false_activation",
                    "accuracy_px",    "bias_rms_px",         "noise_std_px",
                    "worst_error_px", "p_detect_min",        "detected_fraction",
                    "p_detect",       "accuracy_clean_px",   "p_outlier"};
  const size_t n_metrics = r.metric_names.size();
  // Points are independent: the rows share the cores, the grid is the same for any thread count.
  scan_grid(
      r,
      [&](size_t ib, size_t is) {
        return to_eval_point(evaluate_demod_point(cfg, r.signal.values[is], r.background.values[ib]), n_metrics);
      },
      progress, sink, true);
  r.signal_range = demod_signal_range(cfg, r.background.values.front(), r.signal.values);
  r.background_range = demod_background_range(cfg, r.signal.values.back(), r.background.values);
  r.distance_m = cfg.optics.distance_m;
  const double per_px = demod_range_per_px_m(cfg);
  r.summary_extra = {{"range_per_px_m", per_px},
                     {"accuracy_min_px", r.accuracy_min_m / per_px},
                     {"accuracy_max_px", r.accuracy_max_m / per_px},
                     {"frames_averaged", g.frames_averaged},
                     {"detections", g.detections},
                     {"frame_rate_Hz", 1 / demod_frame_time_s(cfg, g.detections)},
                     {"even_harmonic_selectivity_dB", harmonic_selectivity_dB(cfg, g.sweep_background_A, 2)},
                     {"lpf_settling_1pct_s", step_settling_time_s(cfg, 0.01)}};
  r.sweeps = demod_sweeps(cfg);
  return r;
}

}  // namespace

EvalResult evaluate_ls_demodulation(const ParamSet& params, ProgressFn progress) {
  return evaluate_grid(params, progress, nullptr);
}

EvalResult evaluate_ls_demodulation_streamed(const ParamSet& params, ProgressFn progress, EvalSink& sink) {
  return evaluate_grid(params, progress, &sink);
}

std::vector<PublishedFigure> published_figures_ls_demodulation(const ParamSet& params) {
  return demod_published_figures(ls_demodulation_from_params(params));
}

}  // namespace rangesim::golden
