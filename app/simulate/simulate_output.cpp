#include "app/simulate/simulate_output.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "app/plot_style.h"
#include "app/simulate/map_image.h"

namespace rangesim::app {

namespace {

MapImageSpec labelled(const systemc::RangeMap& m, const std::string& what, const std::string& colour_label) {
  MapImageSpec spec;
  spec.x_label = m.x_label;
  spec.y_label = m.y_label;
  spec.first_row = m.first_row;
  spec.title = m.title + " - " + what;
  spec.colour_label = colour_label;
  return spec;
}

int rows_of(const systemc::RangeMap& m) { return static_cast<int>(m.range_m.size()); }
int columns_of(const systemc::RangeMap& m) { return m.range_m.empty() ? 0 : static_cast<int>(m.range_m[0].size()); }

// Whether some pixel has both a range and a truth (the error image has something to show).
bool has_error(const systemc::RangeMap& m) {
  for (std::size_t r = 0; r < m.range_m.size() && r < m.truth_m.size(); ++r)
    for (std::size_t c = 0, n = std::min(m.range_m[r].size(), m.truth_m[r].size()); c < n; ++c)
      if (std::isfinite(m.range_m[r][c] - m.truth_m[r][c])) return true;
  return false;
}

void draw_range(const std::string& path, const systemc::RangeMap& m) {
  MapImageSpec spec = labelled(m, "valid ranges (blank: invalid)", "range [m]");
  const auto [lo, hi] = finite_range(m.range_m);
  if (std::isfinite(lo)) {
    // A flat map still gets a colour range: +-1e-9 of its value.
    const double pad = hi > lo ? 0.0 : 1e-9 * std::max(1.0, std::fabs(hi));
    spec.lo = lo - pad, spec.hi = hi + pad;
  }
  MapImageWriter().write(
      path, rows_of(m), columns_of(m),
      [&m](int r, double* v) {
        const std::vector<double>& row = m.range_m[static_cast<std::size_t>(r)];
        std::copy(row.begin(), row.end(), v);
      },
      spec);
}

// The error where both the range and the truth exist, symmetric about 0 to the 99th percentile of
// |error|: a few edge pixels must not wash the rest out; beyond it the end colours show.
void draw_error(const std::string& path, const systemc::RangeMap& m) {
  MapImageSpec spec = labelled(m, "range error (colours clipped at the 99th percentile)", "range - truth [m]");
  const double span = std::max(abs_difference_quantile(m.range_m, m.truth_m, 0.99), 1e-9);
  spec.lo = -span, spec.hi = span;
  spec.palette = MapPalette::Diverging;
  MapImageWriter().write(
      path, rows_of(m), columns_of(m),
      [&m](int r, double* v) {
        const auto i = static_cast<std::size_t>(r);
        const std::vector<double>& range = m.range_m[i];
        const std::size_t n = i < m.truth_m.size() ? std::min(range.size(), m.truth_m[i].size()) : 0;
        for (std::size_t j = 0; j < n; ++j) v[j] = range[j] - m.truth_m[i][j];
        std::fill(v + n, v + range.size(), NAN);
      },
      spec);
}

}  // namespace

std::vector<std::function<void()>> range_map_image_jobs(OutputDir& out, const systemc::RangeMap& m) {
  const std::string range_path = out.staged("range_map.png");
  std::vector<std::function<void()>> jobs;
  if (has_error(m)) jobs.emplace_back([path = out.staged("range_error.png"), &m] { draw_error(path, m); });
  jobs.emplace_back([range_path, &m] { draw_range(range_path, m); });
  return jobs;
}

}  // namespace rangesim::app
