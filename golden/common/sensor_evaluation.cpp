#include "golden/common/sensor_evaluation.h"

#include <algorithm>
#include <cmath>

namespace rangesim::golden {

namespace {

void widen(double v, double& lo, double& hi) {
  if (!std::isfinite(v)) return;
  lo = std::isnan(lo) ? v : std::min(lo, v);
  hi = std::isnan(hi) ? v : std::max(hi, v);
}

}  // namespace

void PointSummary::add(const EvalPoint& p) {
  if (p.detect != "detectable") return;
  ++detectable_;
  widen(p.sbr_total_dB, sbr_min_, sbr_max_);
  widen(p.sbr_ratio_dB, ratio_min_, ratio_max_);
  widen(p.accuracy_m, acc_min_, acc_max_);
}

void PointSummary::into(EvalResult& r) const {
  r.points_detectable = detectable_;
  r.sbr_min_dB = sbr_min_, r.sbr_max_dB = sbr_max_;
  r.sbr_ratio_min_dB = ratio_min_, r.sbr_ratio_max_dB = ratio_max_;
  r.accuracy_min_m = acc_min_, r.accuracy_max_m = acc_max_;
}

void summarise_points(EvalResult& r) {
  PointSummary s;
  for (const auto& p : r.points) s.add(p);
  s.into(r);
}

std::vector<double> log_spaced(double lo, double hi, int n) {
  std::vector<double> v(static_cast<size_t>(std::max(n, 0)));
  if (n == 1) v[0] = lo;
  for (int i = 0; n > 1 && i < n; ++i)
    v[static_cast<size_t>(i)] = i == n - 1 ? hi : lo * std::pow(hi / lo, static_cast<double>(i) / (n - 1));
  return v;
}

}  // namespace rangesim::golden
