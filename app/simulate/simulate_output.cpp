#include "app/simulate/simulate_output.h"

#include <algorithm>
#include <cmath>

#include "app/plot_style.h"
#include "app/simulate/map_image.h"

namespace rangesim::app {

namespace {

// The map's error where both the range and the truth exist.
std::vector<std::vector<double>> error_rows(const systemc::RangeMap& m) {
  std::vector<std::vector<double>> e = m.range_m;
  for (std::size_t r = 0; r < e.size(); ++r)
    for (std::size_t c = 0; c < e[r].size(); ++c)
      e[r][c] = r < m.truth_m.size() && c < m.truth_m[r].size() ? m.range_m[r][c] - m.truth_m[r][c] : NAN;
  return e;
}

// The q-quantile of |v| over the finite values (0 when none).
double abs_quantile(const std::vector<std::vector<double>>& rows, double q) {
  std::vector<double> a;
  for (const auto& r : rows)
    for (double v : r)
      if (std::isfinite(v)) a.push_back(std::fabs(v));
  if (a.empty()) return 0;
  const auto k = static_cast<std::size_t>(q * static_cast<double>(a.size() - 1));
  std::nth_element(a.begin(), a.begin() + static_cast<std::ptrdiff_t>(k), a.end());
  return a[k];
}

}  // namespace

std::string render_range_map(OutputDir& out, const systemc::RangeMap& m) {
  MapImageSpec spec;
  spec.x_label = m.x_label;
  spec.y_label = m.y_label;
  spec.first_row = m.first_row;
  spec.title = m.title + " - valid ranges (blank: invalid)";
  spec.colour_label = "range [m]";
  const auto [lo, hi] = finite_range(m.range_m);
  if (std::isfinite(lo)) {
    // A flat map still gets a colour range: +-1e-9 of its value.
    const double pad = hi > lo ? 0.0 : 1e-9 * std::max(1.0, std::fabs(hi));
    spec.lo = lo - pad, spec.hi = hi + pad;
  }
  write_map_image(out.staged("range_map.png"), m.range_m, spec);
  const std::vector<std::vector<double>> err = error_rows(m);
  if (std::isfinite(finite_range(err).first)) {
    // Symmetric about 0 to the 99th percentile of |error|: a few edge pixels must not wash the rest
    // out; beyond it the end colours show.
    const double span = std::max(abs_quantile(err, 0.99), 1e-9);
    spec.title = m.title + " - range error";
    spec.colour_label = "range - ground truth [m] (clipped at the 99th percentile)";
    spec.lo = -span, spec.hi = span;
    spec.palette = MapPalette::Diverging;
    write_map_image(out.staged("range_error.png"), err, spec);
  }
  return "";
}

}  // namespace rangesim::app
