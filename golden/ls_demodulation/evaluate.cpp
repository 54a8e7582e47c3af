// ls-demodulation's evaluation over the signal x background grid as an EvalResult, its sweeps
// (thesis Fig. 3.6, 3.8, 3.9, selectivity, step settling) and its published figures.
#include <algorithm>
#include <atomic>
#include <cmath>
#include <thread>

#include "core/ls_demodulation/config.h"
#include "golden/common/evaluate_sensor.h"
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
  }
  return q;
}

// Evaluates f(i) for i < n over the cores; results depend only on i (thread-count independent).
template <class F>
void parallel_for(int n, F f, ProgressFn progress, int unit) {
  std::atomic<int> next{0}, done{0};
  auto work = [&](bool report) {
    for (int i; (i = next.fetch_add(1)) < n;) {
      f(i);
      const int d = done.fetch_add(1) + 1;
      if (report && progress) progress(d * unit, n * unit);
    }
  };
  const unsigned hw = std::max(1u, std::thread::hardware_concurrency());
  std::vector<std::thread> pool;
  for (unsigned t = 1; t < std::min<unsigned>(hw, static_cast<unsigned>(n)); ++t) pool.emplace_back(work, false);
  try {
    work(true);
  } catch (...) {  // the progress callback cancelled the run: hand out nothing more, join, pass it on
    next.store(n);
    for (auto& t : pool) t.join();
    throw;
  }
  for (auto& t : pool) t.join();
}

}  // namespace

EvalResult evaluate_ls_demodulation(const ParamSet& params, ProgressFn progress) {
  const LsDemodulationConfig cfg = ls_demodulation_from_params(params);
  const auto& g = cfg.grid;
  EvalResult r;
  r.sensor = params.sensor_id();
  r.signal = {"signal", "A", log_spaced(g.signal_min_A, g.signal_max_A, g.signal_points)};
  r.background = {"background", "A", log_spaced(g.background_min_A, g.background_max_A, g.background_points)};
  r.reasons = {{"detectable", "range can be derived"},
               {"below_threshold", "noise-free V_out+ - V_out- at the spot peak stays below V_cmp"},
               {"saturated", "an integrator swing exceeds V_sat (background alone or with the spot)"},
               {"background_activation",
                "background alone reaches V_cmp, or its noise activates more than "
                "comparator.false_activation_max of the rows"}};
  r.metric_names = {"peak_output_V",    "background_output_V", "row_false_activation", "accuracy_px",
                    "bias_rms_px",      "noise_std_px",        "worst_error_px",       "p_detect",
                    "detected_fraction"};
  const int ns = static_cast<int>(r.signal.values.size()), nb = static_cast<int>(r.background.values.size());
  r.points.assign(static_cast<size_t>(ns) * nb, EvalPoint{});
  parallel_for(
      nb,
      [&](int ib) {
        for (int is = 0; is < ns; ++is)
          r.points[static_cast<size_t>(ib) * ns + is] = to_eval_point(
              evaluate_demod_point(cfg, r.signal.values[is], r.background.values[ib]), r.metric_names.size());
      },
      progress, ns);
  if (progress) progress(nb * ns, nb * ns);
  summarise_points(r);
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

std::vector<PublishedFigure> published_figures_ls_demodulation(const ParamSet& params) {
  return demod_published_figures(ls_demodulation_from_params(params));
}

}  // namespace rangesim::golden
