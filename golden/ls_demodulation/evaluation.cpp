#include "golden/ls_demodulation/evaluation.h"

#include <cmath>

#include "golden/ls_demodulation/fixed_pattern.h"

namespace rangesim::golden {

DemodPoint evaluate_demod_point(const LsDemodulationConfig& cfg, double s, double b, int K, int Np) {
  DemodPoint p;
  p.signal_A = s, p.background_A = b;
  p.sbr_total_dB = 20 * std::log10((s + b) / b);
  p.sbr_ratio_dB = 20 * std::log10(s / b);
  const Classification c = classify(cfg, s, b);
  p.detect = c.detect;
  p.peak_output_V = c.peak.out.diff_V;
  p.background_output_V = c.background.out.diff_V;
  p.row_false_activation = c.row_false_activation;
  if (p.detect == DemodDetect::Detectable) p.accuracy = accuracy_with_fixed_offsets(cfg, s, b, K, Np);
  return p;
}

DemodPoint evaluate_demod_point(const LsDemodulationConfig& cfg, double s, double b) {
  return evaluate_demod_point(cfg, s, b, cfg.grid.detections, cfg.grid.frames_averaged);
}

bool demod_detectable(const LsDemodulationConfig& cfg, double s, double b) {
  return classify(cfg, s, b).detect == DemodDetect::Detectable;
}

namespace {

// Edge between a detectable value `in` and a non-detectable `out` (log bisection).
template <class F>
double bisect_edge(F ok, double in, double out) {
  double a = std::log(in), z = std::log(out);
  for (int i = 0; i < 60; ++i) {
    const double m = 0.5 * (a + z);
    (ok(std::exp(m)) ? a : z) = m;
  }
  return std::exp(a);
}

template <class F>
EvalRange range_along(F ok, const std::vector<double>& axis, double at) {
  EvalRange r;
  r.at = at;
  int first = -1, last = -1;
  for (int i = 0; i < static_cast<int>(axis.size()); ++i)
    if (ok(axis[i])) {
      if (first < 0) first = i;
      last = i;
    }
  if (first < 0) return r;
  const int n = static_cast<int>(axis.size());
  r.lo_limited_by_grid = first == 0;
  r.hi_limited_by_grid = last == n - 1;
  r.lo = first == 0 ? axis[0] : bisect_edge(ok, axis[first], axis[first - 1]);
  r.hi = last == n - 1 ? axis[n - 1] : bisect_edge(ok, axis[last], axis[last + 1]);
  r.range_dB = 20 * std::log10(r.hi / r.lo);
  return r;
}

}  // namespace

EvalRange demod_signal_range(const LsDemodulationConfig& cfg, double b, const std::vector<double>& axis) {
  return range_along([&](double s) { return demod_detectable(cfg, s, b); }, axis, b);
}

EvalRange demod_background_range(const LsDemodulationConfig& cfg, double s, const std::vector<double>& axis) {
  return range_along([&](double b) { return demod_detectable(cfg, s, b); }, axis, s);
}

double min_detectable_signal_A(const LsDemodulationConfig& cfg, double b, double lo, double hi) {
  auto ok = [&](double s) { return demod_detectable(cfg, s, b); };
  if (ok(lo)) return lo;
  // Scan up for the first detectable value (the set need not be an interval), then bisect.
  const int n = 200;
  double prev = lo;
  for (int i = 1; i <= n; ++i) {
    const double s = lo * std::pow(hi / lo, static_cast<double>(i) / n);
    if (ok(s)) return bisect_edge(ok, s, prev);
    prev = s;
  }
  return std::nan("");
}

double demod_frame_time_s(const LsDemodulationConfig& cfg, int K) {
  return K * cfg.pixel.integration_time_s + cfg.pixel.rows * cfg.readout.row_cycles / cfg.readout.clock_Hz;
}

}  // namespace rangesim::golden
