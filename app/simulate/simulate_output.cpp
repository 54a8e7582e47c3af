#include "app/simulate/simulate_output.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

#include "app/matrix_rows.h"
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

// Whether some pixel has both a range and a truth (the error image has something to show).
bool has_error(const systemc::RangeMap& m) {
  for (std::size_t r = 0; r < m.range_m.size() && r < m.truth_m.size(); ++r)
    for (std::size_t c = 0, n = std::min(m.range_m[r].size(), m.truth_m[r].size()); c < n; ++c)
      if (std::isfinite(m.range_m[r][c] - m.truth_m[r][c])) return true;
  return false;
}

int columns_of(MatrixRows m) { return m.empty() ? 0 : static_cast<int>(m[0].size()); }

// The map's valid ranges on viridis from their smallest to their largest.
void draw_range(MapImageWriter& writer, const std::string& path, MatrixRows range, MapImageSpec spec) {
  const auto [lo, hi] = finite_range(range);
  if (std::isfinite(lo)) {
    // A flat map still gets a colour range: +-1e-9 of its value.
    const double pad = hi > lo ? 0.0 : 1e-9 * std::max(1.0, std::fabs(hi));
    spec.lo = lo - pad, spec.hi = hi + pad;
  }
  writer.write(
      path, static_cast<int>(range.size()), columns_of(range),
      [range](int r, double* v) {
        const std::vector<double>& row = range[static_cast<std::size_t>(r)];
        std::copy(row.begin(), row.end(), v);
      },
      spec);
}

// The error where both the range and the truth exist, symmetric about 0 to the 99th percentile of
// |error|: a few edge pixels must not wash the rest out; beyond it the end colours show.
void draw_error(MapImageWriter& writer, const std::string& path, MatrixRows range, MatrixRows truth,
                MapImageSpec spec) {
  const double span = std::max(abs_difference_quantile(range, truth, 0.99), 1e-9);
  spec.lo = -span, spec.hi = span;
  spec.palette = MapPalette::Diverging;
  writer.write(
      path, static_cast<int>(range.size()), columns_of(range),
      [range, truth](int r, double* v) {
        const auto i = static_cast<std::size_t>(r);
        const std::vector<double>& row = range[i];
        const std::size_t n = i < truth.size() ? std::min(row.size(), truth[i].size()) : 0;
        for (std::size_t j = 0; j < n; ++j) v[j] = row[j] - truth[i][j];
        std::fill(v + n, v + row.size(), NAN);
      },
      spec);
}

// A writer whose memory is taken on the calling thread (MapImageWriter::reserve).
std::shared_ptr<MapImageWriter> writer_for(const systemc::RangeMap& m, const MapImageSpec& spec) {
  auto writer = std::make_shared<MapImageWriter>();
  writer->reserve(static_cast<int>(m.range_m.size()), columns_of(m.range_m), spec);
  return writer;
}

}  // namespace

std::function<void()> range_image_job(OutputDir& out, const systemc::RangeMap& m) {
  const MapImageSpec spec = labelled(m, "valid ranges (blank: invalid)", "range [m]");
  return [path = out.staged("range_map.png"), range = MatrixRows(m.range_m), spec, writer = writer_for(m, spec)] {
    draw_range(*writer, path, range, spec);
  };
}

std::function<void()> error_image_job(OutputDir& out, const systemc::RangeMap& m) {
  if (!has_error(m)) return {};
  const MapImageSpec spec = labelled(m, "range error (colours clipped at the 99th percentile)", "range - truth [m]");
  return [path = out.staged("range_error.png"), range = MatrixRows(m.range_m), truth = MatrixRows(m.truth_m), spec,
          writer = writer_for(m, spec)] { draw_error(*writer, path, range, truth, spec); };
}

}  // namespace rangesim::app
