#include "app/simulate/simulate_output.h"

#include <algorithm>
#include <cmath>

#include "app/plot_style.h"
#include "app/simulate/map_image.h"

namespace rangesim::app {

namespace {

// The q-quantile of |e| over the finite errors e = range - truth (-1 when none), in single
// precision: the colour scale's end, not a figure (half the memory of doubles).
double abs_quantile(const systemc::RangeMap& m, double q) {
  std::vector<float> a;
  a.reserve(m.range_m.size() * (m.range_m.empty() ? 0 : m.range_m[0].size()));
  for (std::size_t r = 0; r < m.range_m.size() && r < m.truth_m.size(); ++r)
    for (std::size_t c = 0; c < m.range_m[r].size() && c < m.truth_m[r].size(); ++c) {
      const double e = m.range_m[r][c] - m.truth_m[r][c];
      if (std::isfinite(e)) a.push_back(static_cast<float>(std::fabs(e)));
    }
  if (a.empty()) return -1;
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
  const int rows = static_cast<int>(m.range_m.size()), cols = rows ? static_cast<int>(m.range_m[0].size()) : 0;
  MapImageWriter images;
  images.write(
      out.staged("range_map.png"), rows, cols,
      [&m](int r, double* v) {
        const std::vector<double>& row = m.range_m[static_cast<std::size_t>(r)];
        std::copy(row.begin(), row.end(), v);
      },
      spec);
  // The error where both the range and the truth exist, symmetric about 0 to the 99th percentile of
  // |error|: a few edge pixels must not wash the rest out; beyond it the end colours show.
  const double q99 = abs_quantile(m, 0.99);
  if (q99 >= 0) {
    const double span = std::max(q99, 1e-9);
    spec.title = m.title + " - range error (colours clipped at the 99th percentile)";
    spec.colour_label = "range - truth [m]";
    spec.lo = -span, spec.hi = span;
    spec.palette = MapPalette::Diverging;
    images.write(
        out.staged("range_error.png"), rows, cols,
        [&m](int r, double* v) {
          const std::vector<double>& range = m.range_m[static_cast<std::size_t>(r)];
          const std::vector<double>* truth =
              static_cast<std::size_t>(r) < m.truth_m.size() ? &m.truth_m[static_cast<std::size_t>(r)] : nullptr;
          for (std::size_t j = 0; j < range.size(); ++j)
            v[j] = truth && j < truth->size() ? range[j] - (*truth)[j] : NAN;
        },
        spec);
  }
  return "";
}

}  // namespace rangesim::app
