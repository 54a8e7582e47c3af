// The map images' colour and scale helpers (app/simulate/map_image.h, finite_range of
// app/plot_style.h) against plain reference computations written here.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "app/plot_style.h"
#include "app/simulate/map_image.h"

namespace {

using rangesim::app::abs_difference_quantile;
using rangesim::app::finite_range;
using rangesim::app::map_row_colours;

// The documented rule, one cell at a time: 0 (paper) where the value is not finite, otherwise the
// ramp's 254 colours from index 2, x = (v - lo) / span clamped to [0, 1], x 253 rounded half up.
std::uint8_t reference_colour(double v, double lo, double span) {
  if (!std::isfinite(v)) return 0;
  const double y = std::min(std::max((v - lo) / span, 0.0), 1.0) * 253;
  const int k = static_cast<int>(y);
  return static_cast<std::uint8_t>(2 + k + static_cast<int>(2 * (y - k)));
}

TEST(MapImage, RowColoursEqualTheScalarRamp) {
  const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
  const double lo = 0.9, span = 0.25;
  std::vector<double> v = {nan,
                           inf,
                           -inf,
                           lo - 1,
                           lo,
                           lo + span,
                           lo + span * 2,
                           -0.0,
                           0.0,
                           std::numeric_limits<double>::max(),
                           std::numeric_limits<double>::denorm_min()};
  for (int k = 0; k <= 253; ++k) {  // every colour's edges: the half-way points and their neighbours
    const double half = lo + span * (k + 0.5) / 253;
    v.insert(v.end(), {half, std::nextafter(half, -inf), std::nextafter(half, inf), lo + span * k / 253.0});
  }
  std::mt19937_64 g(3);
  std::uniform_real_distribution<double> u(lo - 0.1, lo + span + 0.1);
  for (int i = 0; i < 5000; ++i) v.push_back(i % 17 == 0 ? nan : u(g));
  // Every length from 0 to 9 and every start, so that each cell is once in the four-wide steps and
  // once in the tail.
  for (std::size_t start = 0; start < 4; ++start)
    for (std::size_t n = 0; n + start <= v.size(); n += (n < 9 ? 1 : 997)) {
      std::vector<std::uint8_t> out(n + 1, 0xee);
      map_row_colours(v.data() + start, static_cast<int>(n), lo, span, out.data());
      for (std::size_t c = 0; c < n; ++c)
        ASSERT_EQ(out[c], reference_colour(v[start + c], lo, span)) << "value " << v[start + c] << " at " << c;
      EXPECT_EQ(out[n], 0xee) << "wrote past the row, n " << n;
    }
}

TEST(MapImage, DifferenceQuantileIsTheKthSmallest) {
  std::mt19937_64 g(5);
  std::normal_distribution<double> e(0, 1.3e-3);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<std::vector<double>> range(37, std::vector<double>(41)), truth = range;
  std::vector<float> reference;
  for (std::size_t r = 0; r < range.size(); ++r)
    for (std::size_t c = 0; c < range[r].size(); ++c) {
      truth[r][c] = 1.0 + 0.01 * static_cast<double>(c);
      // Invalid pixels (NaN range), pixels without truth, and errors repeated as a quantised
      // centre repeats them.
      range[r][c] = c % 7 == 3 ? nan : truth[r][c] + std::round(e(g) / 6e-5) * 6e-5;
      if (r % 11 == 5) truth[r][c] = nan;
      const double d = range[r][c] - truth[r][c];
      if (std::isfinite(d)) reference.push_back(static_cast<float>(std::fabs(d)));
    }
  std::sort(reference.begin(), reference.end());
  for (const double q : {0.0, 0.25, 0.5, 0.99, 0.999, 1.0}) {
    const auto k = static_cast<std::size_t>(q * static_cast<double>(reference.size() - 1));
    EXPECT_EQ(abs_difference_quantile(range, truth, q), reference[k]) << "q " << q;
  }
  // Ragged rows count only the cells both have; nothing to measure gives -1.
  range[0].resize(5);
  EXPECT_GE(abs_difference_quantile(range, truth, 0.5), 0.0);
  const std::vector<std::vector<double>> empty(3, std::vector<double>(4, nan));
  EXPECT_EQ(abs_difference_quantile(empty, truth, 0.99), -1.0);
}

// A full map's size, where the quantile orders only the values at or above a sampled threshold:
// noise quantised as a centre quantises it (ties at the threshold), sorted maps both ways, a
// constant map, and a map whose every 32nd value is the largest (no invalid cells there, so the
// sample is those: the threshold is too high and the whole copy is ordered). Every q against a sort.
TEST(MapImage, DifferenceQuantileOfAFullMapIsTheKthSmallest) {
  const std::size_t rows = 375, cols = 366;
  std::mt19937_64 g(11);
  std::normal_distribution<double> e(0, 1.3e-3);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  auto error = [&](int kind, std::size_t i) {
    switch (kind) {
      case 0: return std::round(e(g) / 6e-5) * 6e-5;
      case 1: return 1e-6 * static_cast<double>(i);
      case 2: return -1e-6 * static_cast<double>(rows * cols - i);
      case 3: return 2.5e-3;
      default: return i % 32 == 0 ? 1.0 + 1e-6 * static_cast<double>(i) : 1e-3 * std::fabs(e(g));
    }
  };
  for (int kind = 0; kind < 5; ++kind) {
    std::vector<std::vector<double>> range(rows, std::vector<double>(cols)), truth = range;
    std::vector<float> reference;
    for (std::size_t r = 0; r < rows; ++r)
      for (std::size_t c = 0; c < cols; ++c) {
        truth[r][c] = 1.0 + 0.001 * static_cast<double>(c);
        range[r][c] = c % 9 == 4 && kind != 4 ? nan : truth[r][c] + error(kind, r * cols + c);
        const double d = range[r][c] - truth[r][c];
        if (std::isfinite(d)) reference.push_back(static_cast<float>(std::fabs(d)));
      }
    std::sort(reference.begin(), reference.end());
    for (const double q : {0.0, 0.5, 0.9, 0.98, 0.99, 0.995, 0.999, 1.0}) {
      const auto k = static_cast<std::size_t>(q * static_cast<double>(reference.size() - 1));
      EXPECT_EQ(abs_difference_quantile(range, truth, q), reference[k]) << "kind " << kind << " q " << q;
    }
  }
}

// The vector minimum and maximum against the scalar rule, rows of every length 0 to 20 and a
// map's width, values not finite at random places and at the rows' ends.
TEST(MapImage, FiniteRangeSkipsWhatIsNotFinite) {
  std::mt19937_64 g(3);
  std::uniform_real_distribution<double> u(-5, 5);
  const double special[] = {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity(),
                            -std::numeric_limits<double>::infinity()};
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<std::vector<double>> rows;
    double lo = INFINITY, hi = -INFINITY;
    for (std::size_t len : {static_cast<std::size_t>(trial % 21), std::size_t{366}, std::size_t{9}}) {
      std::vector<double> row(len);
      for (std::size_t i = 0; i < len; ++i) {
        row[i] = g() % 4 == 0 ? special[g() % 3] : u(g) * (1 + trial);
        if (std::isfinite(row[i])) lo = std::min(lo, row[i]), hi = std::max(hi, row[i]);
      }
      rows.push_back(row);
    }
    const auto [a, b] = finite_range(rows);
    if (lo > hi) {
      EXPECT_TRUE(std::isnan(a) && std::isnan(b)) << "trial " << trial;
    } else {
      EXPECT_EQ(a, lo) << "trial " << trial;
      EXPECT_EQ(b, hi) << "trial " << trial;
    }
  }
  const std::vector<std::vector<double>> none(2, std::vector<double>(17, std::numeric_limits<double>::quiet_NaN()));
  EXPECT_TRUE(std::isnan(finite_range(none).first));
}

}  // namespace
