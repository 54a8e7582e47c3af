#include "golden/tof_spad/ranges.h"

#include <algorithm>
#include <cmath>

namespace rangesim::golden::spad {

namespace {

// Edge between a detectable x_in and an undetectable x_out, by bisection in log x.
double bisect_edge(double x_in, double x_out, const std::function<bool(double)>& detectable) {
  double a = std::log(x_in), b = std::log(x_out);
  while (std::fabs(b - a) > 1e-4) {
    const double m = 0.5 * (a + b);
    (detectable(std::exp(m)) ? a : b) = m;
  }
  return std::exp(0.5 * (a + b));
}

}  // namespace

EvalRange detectable_range(const std::vector<double>& axis, const std::vector<bool>& ok,
                           const std::function<bool(double)>& detectable, double at) {
  EvalRange r;
  r.at = at;
  const auto first = std::find(ok.begin(), ok.end(), true);
  if (first == ok.end()) return r;
  const size_t i0 = static_cast<size_t>(first - ok.begin());
  size_t i1 = i0;
  while (i1 + 1 < ok.size() && ok[i1 + 1]) ++i1;
  r.lo_limited_by_grid = i0 == 0;
  r.hi_limited_by_grid = i1 + 1 == ok.size();
  r.lo = r.lo_limited_by_grid ? axis[i0] : bisect_edge(axis[i0], axis[i0 - 1], detectable);
  r.hi = r.hi_limited_by_grid ? axis[i1] : bisect_edge(axis[i1], axis[i1 + 1], detectable);
  r.range_dB = 20 * std::log10(r.hi / r.lo);
  return r;
}

std::vector<double> linear_spaced(double lo, double hi, int n) {
  std::vector<double> v(static_cast<size_t>(std::max(n, 1)), lo);
  for (int i = 1; i < n; ++i) v[static_cast<size_t>(i)] = lo + (hi - lo) * i / (n - 1);
  return v;
}

Nonlinearity nonlinearity(const SpadModel& model, double signal_Hz, double background_Hz,
                          const std::vector<double>& d) {
  Nonlinearity n;
  n.distance_m = d;
  for (double x : d) {
    const PointResult p = model.evaluate(signal_Hz, background_Hz, x);
    n.bias_m.push_back(p.bias_m);
    n.std_m.push_back(p.std_m);
    n.max_abs_bias_m = std::max(n.max_abs_bias_m, std::fabs(p.bias_m));
  }
  // Least-squares line through (d, bias): measured = d + bias, calibrated by offset and gain.
  const double m = static_cast<double>(d.size());
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (size_t i = 0; i < d.size(); ++i) {
    sx += d[i], sy += n.bias_m[i], sxx += d[i] * d[i], sxy += d[i] * n.bias_m[i];
  }
  const double det = m * sxx - sx * sx;
  const double slope = det > 0 ? (m * sxy - sx * sy) / det : 0, offset = (sy - slope * sx) / m;
  for (size_t i = 0; i < d.size(); ++i)
    n.max_deviation_m = std::max(n.max_deviation_m, std::fabs(n.bias_m[i] - offset - slope * d[i]));
  return n;
}

}  // namespace rangesim::golden::spad
