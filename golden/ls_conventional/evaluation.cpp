#include "golden/common/grid_axes.h"
#include "golden/ls_conventional/evaluation.h"

#include <algorithm>
#include <atomic>
#include <thread>
#include <cmath>
#include <limits>

#include "golden/ls_conventional/detect.h"
#include "golden/ls_conventional/multisampling.h"
#include "golden/ls_conventional/subpixel_average.h"
#include "golden/common/pixel.h"
#include "golden/common/position_noise.h"
#include "golden/common/quantiser.h"
#include "golden/common/row_model.h"
#include "golden/common/sbr.h"
#include "golden/common/threshold.h"
#include "golden/common/triangulation.h"

namespace rangesim::golden {

const char* to_string(Detect d) {
  switch (d) {
    case Detect::Detectable: return "detectable";
    case Detect::BelowThreshold: return "below_threshold";
    case Detect::Saturated: return "saturated";
    case Detect::BackgroundActivation: return "background_activation";
  }
  return "?";
}

std::vector<double> log_axis(double lo, double hi, int n) {
  if (n <= 1) return {lo};
  std::vector<double> a(n);
  const double r = std::log(hi / lo);
  for (int i = 0; i < n; ++i) a[i] = lo * std::exp(r * i / (n - 1));
  a.back() = hi;  // exact end point
  return a;
}

OperatingPoint evaluate_point(const LsConventionalConfig& cfg, double signal_V, double background_V) {
  OperatingPoint p;
  p.signal_V = signal_V;
  p.background_V = background_V;
  p.sbr_total_dB = sbr_total_dB(signal_V, background_V);
  p.sbr_ratio_dB = sbr_ratio_dB(signal_V, background_V);
  p.detect = classify(cfg, signal_V, background_V);
  p.noise_exact = cfg.comparator.adc_bits == 1;
  p.noise_method = p.noise_exact ? "exact" : "delta";
  if (p.detect != Detect::Detectable) return p;

  const RowModel row = make_row_model(cfg, signal_V, background_V);
  // Noise-free part: exact integral over the breakpoints.
  const QuantisationError q = quantisation_error(row);
  p.quantisation_rms_px = q.rms_px;
  p.resolution_px = q.resolution_px;
  p.worst_error_px = q.worst_px;
  p.largest_step_px = q.largest_step_px;
  p.detected_fraction = q.detected_fraction;

  // Noise part: the exact moments averaged over the spot positions across a pixel, adaptively to
  // evaluation.subpixel_tolerance (subpixel_average.h). The multi-bit moments are first-order (the
  // delta method) and cost every code level near a pixel's mean: refining an approximation to 1e-3
  // buys nothing and a 14-bit row took minutes, so they take the fixed rule of subpixel_points.
  constexpr int kMaxPositions = 4096;
  const double tolerance = cfg.comparator.adc_bits == 1 ? cfg.grid.subpixel_tolerance : 0.0;
  const SubpixelAverage a =
      subpixel_average(row, q, tolerance, std::clamp(cfg.grid.subpixel_points, 1, kMaxPositions), kMaxPositions);
  p.p_detect = a.p_detect;
  p.accuracy_px = a.accuracy_px;
  p.accuracy_clean_px = a.accuracy_clean_px;
  p.p_outlier = a.p_outlier;
  p.noise_std_px = a.noise_std_px;
  p.noise_only_detections = a.noise_only_detections;
  p.subpixel_positions = a.positions;
  p.subpixel_error_estimate = a.error_estimate;
  p.subpixel_converged = a.converged;
  const double m_per_px = range_per_px_m(cfg.optics, cfg.pixel.pitch_m, cfg.optics.distance_m);
  p.accuracy_m = p.accuracy_px * m_per_px;
  p.accuracy_clean_m = p.accuracy_clean_px * m_per_px;
  return p;
}

namespace {

DynamicRange make_range(double lo, double hi, double lo_limit, double hi_limit) {
  DynamicRange r;
  r.lo_limited_by_grid = lo <= lo_limit;
  r.hi_limited_by_grid = hi >= hi_limit;
  lo = std::max(lo, lo_limit);
  hi = std::min(hi, hi_limit);
  if (!(lo <= hi) || !(lo > 0)) return {};
  r.lo_V = lo;
  r.hi_V = hi;
  r.range_dB = 20 * std::log10(hi / lo);
  return r;
}

bool background_activates(const LsConventionalConfig& cfg, double background_V) {
  const double A = cfg.pixel.source_follower_gain;
  if (reaches_threshold(A * (background_V + dark_voltage_V(cfg.pixel)), comparator_threshold_V(cfg, background_V)))
    return true;
  return row_false_activation_probability(cfg, background_V) > cfg.comparator.false_activation_max;
}

}  // namespace

DynamicRange signal_dynamic_range(const LsConventionalConfig& cfg, double background_V, double lo_limit_V,
                                  double hi_limit_V) {
  // Both edges in closed form: the background criteria do not depend on the signal.
  if (background_activates(cfg, background_V)) return {};
  const double A = cfg.pixel.source_follower_gain, dark = dark_voltage_V(cfg.pixel);
  const double lo = comparator_threshold_V(cfg, background_V) / A - background_V - dark;  // reaches theta
  const double hi = cfg.pixel.saturation_voltage_V - background_V - dark;                 // eq. 3.3
  return make_range(lo, hi, lo_limit_V, hi_limit_V);
}

DynamicRange background_dynamic_range(const LsConventionalConfig& cfg, double signal_V, double lo_limit_V,
                                      double hi_limit_V) {
  const double A = cfg.pixel.source_follower_gain, dark = dark_voltage_V(cfg.pixel);
  double lo = 0;
  double hi = cfg.pixel.saturation_voltage_V - signal_V - dark;  // saturation edge (inclusive)
  if (cfg.comparator.threshold_mode == ThresholdMode::Tracking) {
    // theta follows the background: the peak reaches it iff A V_sig >= Delta V_ADC, any background.
    if (below_threshold(A * signal_V, cfg.comparator.threshold_above_background_V)) return {};
  } else {
    const double theta = cfg.comparator.fixed_threshold_V;
    lo = theta / A - signal_V - dark;     // peak reaches the fixed threshold
    hi = std::min(hi, theta / A - dark);  // background alone reaches it (strictly below is fine)
  }
  // Noise: P(any background pixel activates) grows with the background; bisect its edge in log V.
  const double max_p = cfg.comparator.false_activation_max;
  auto noisy = [&](double bg) { return row_false_activation_probability(cfg, bg) > max_p; };
  const double top = std::min(hi, hi_limit_V);
  const double bottom = std::max(lo, lo_limit_V);
  if (bottom > 0 && top >= bottom && noisy(top)) {
    if (noisy(bottom)) return {};
    double a = std::log(bottom), b = std::log(top);  // noisy(e^a) false, noisy(e^b) true
    for (int i = 0; i < 100 && b - a > 1e-15; ++i) {
      const double mid = 0.5 * (a + b);
      (noisy(std::exp(mid)) ? b : a) = mid;
    }
    hi = std::exp(a);
  }
  return make_range(lo, hi, lo_limit_V, hi_limit_V);
}

Evaluation evaluate(const LsConventionalConfig& cfg, void (*progress)(int done, int total)) {
  Evaluation ev;
  const auto& g = cfg.grid;
  ev.signal_V = grid_axis(GridAxis::Signal, log_axis(g.signal_min_V, g.signal_max_V, g.signal_points));
  ev.background_V =
      grid_axis(GridAxis::Background, log_axis(g.background_min_V, g.background_max_V, g.background_points));
  const int ns = static_cast<int>(ev.signal_V.size()), nb = static_cast<int>(ev.background_V.size());
  // Points are independent: background rows are shared out over the cores. Each point's result
  // depends only on its own inputs, so the grid is identical whatever the thread count.
  ev.points.assign(static_cast<size_t>(ns) * nb, OperatingPoint{});
  std::atomic<int> next_row{0}, rows_done{0};
  auto work = [&](bool report) {
    for (int ib; (ib = next_row.fetch_add(1)) < nb;) {
      for (int is = 0; is < ns; ++is)
        ev.points[static_cast<size_t>(ib) * ns + is] = evaluate_point(cfg, ev.signal_V[is], ev.background_V[ib]);
      const int done = rows_done.fetch_add(1) + 1;
      if (report && progress) progress(done * ns, nb * ns);  // only the calling thread reports
    }
  };
  const unsigned hw = std::max(1u, std::thread::hardware_concurrency());
  std::vector<std::thread> pool;
  for (unsigned t = 1; t < std::min<unsigned>(hw, static_cast<unsigned>(nb)); ++t) pool.emplace_back(work, false);
  try {
    work(true);
  } catch (...) {  // the progress callback cancelled the run: hand out no more rows, join, pass it on
    next_row.store(nb);
    for (auto& t : pool) t.join();
    throw;
  }
  for (auto& t : pool) t.join();
  if (progress) progress(nb * ns, nb * ns);

  EvaluationSummary& s = ev.summary;
  s.samplings = cfg.multisampling.samplings;
  s.adc_bits = cfg.comparator.adc_bits;
  s.points_total = ns * nb;
  s.range_per_px_m = range_per_px_m(cfg.optics, cfg.pixel.pitch_m, cfg.optics.distance_m);
  s.signal = signal_dynamic_range(cfg, ev.background_V.front(), g.signal_min_V, g.signal_max_V);
  s.background = background_dynamic_range(cfg, ev.signal_V.back(), g.background_min_V, g.background_max_V);
  const double inf = std::numeric_limits<double>::infinity();
  double sbr_lo = inf, sbr_hi = -inf, rat_lo = inf, rat_hi = -inf, acc_lo = inf, acc_hi = -inf;
  for (const auto& p : ev.points) {
    if (p.detect != Detect::Detectable) continue;
    ++s.points_detectable;
    sbr_lo = std::min(sbr_lo, p.sbr_total_dB);
    sbr_hi = std::max(sbr_hi, p.sbr_total_dB);
    rat_lo = std::min(rat_lo, p.sbr_ratio_dB);
    rat_hi = std::max(rat_hi, p.sbr_ratio_dB);
    acc_lo = std::min(acc_lo, p.accuracy_px);
    acc_hi = std::max(acc_hi, p.accuracy_px);
  }
  if (s.points_detectable > 0) {
    s.sbr_min_dB = sbr_lo;
    s.sbr_max_dB = sbr_hi;
    s.sbr_ratio_min_dB = rat_lo;
    s.sbr_ratio_max_dB = rat_hi;
    s.accuracy_min_px = acc_lo;
    s.accuracy_max_px = acc_hi;
    s.accuracy_min_m = acc_lo * s.range_per_px_m;
    s.accuracy_max_m = acc_hi * s.range_per_px_m;
  }
  return ev;
}

}  // namespace rangesim::golden
