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

void summarise_points(EvalResult& r) {
  r.points_detectable = 0;
  r.sbr_min_dB = r.sbr_max_dB = r.sbr_ratio_min_dB = r.sbr_ratio_max_dB = kNaN;
  r.accuracy_min_m = r.accuracy_max_m = kNaN;
  for (const auto& p : r.points) {
    if (p.detect != "detectable") continue;
    ++r.points_detectable;
    widen(p.sbr_total_dB, r.sbr_min_dB, r.sbr_max_dB);
    widen(p.sbr_ratio_dB, r.sbr_ratio_min_dB, r.sbr_ratio_max_dB);
    widen(p.accuracy_m, r.accuracy_min_m, r.accuracy_max_m);
  }
}

std::vector<double> log_spaced(double lo, double hi, int n) {
  std::vector<double> v(static_cast<size_t>(std::max(n, 0)));
  if (n == 1) v[0] = lo;
  for (int i = 0; n > 1 && i < n; ++i)
    v[static_cast<size_t>(i)] = i == n - 1 ? hi : lo * std::pow(hi / lo, static_cast<double>(i) / (n - 1));
  return v;
}

}  // namespace rangesim::golden
