#include "app/plot_style.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace rangesim::app {

namespace {

// Okabe & Ito, "Color universal design": distinguishable with every common colour-vision deficiency.
const char* kLineColours[] = {"#0072b2", "#d55e00", "#009e73", "#cc79a7", "#e69f00", "#56b4e9", "#000000", "#f0e442"};
const int kPointTypes[] = {7, 5, 9, 11, 13, 4, 6, 8};

}  // namespace

std::string plot_preamble() {
  return "set encoding utf8\nset micro\nset tics out\nset grid lt 0 lw 1 lc rgb '#b0b0b0'\n";
}

std::string viridis_palette() {
  return "set palette defined (0 '#440154', 1 '#482878', 2 '#3e4989', 3 '#31688e', 4 '#26828e', 5 '#1f9e89', "
         "6 '#35b779', 7 '#6ece58', 8 '#b5de2b', 9 '#fde725')\n";
}

std::string diverging_palette() {
  return "set palette defined (0 '#2166ac', 1 '#67a9cf', 2 '#d1e5f0', 3 '#f7f7f7', 4 '#fddbc7', 5 '#ef8a62', "
         "6 '#b2182b')\n";
}

std::string log_format(const std::string& axis, const std::string& unit) {
  static const char* no_prefix[] = {"", "px", "dB", "%", "LSB", "sigma"};
  for (const char* u : no_prefix)
    if (unit == u) return fmt::format("set format {} '%g'\n", axis);
  return fmt::format("set format {} '%.0s%c'\n", axis);
}

std::string log_cbtics(double lo, double hi) {
  if (!(lo > 0) || !(hi >= lo)) return "";
  std::string tics;
  for (int e = static_cast<int>(std::floor(std::log10(lo))); e <= static_cast<int>(std::ceil(std::log10(hi))); ++e)
    for (double m : {1.0, 2.0, 5.0}) {
      const double v = m * std::pow(10.0, e);
      if (v < lo * (1 - 1e-9) || v > hi * (1 + 1e-9)) continue;
      tics += fmt::format("{}\"{:g}\" {:g}", tics.empty() ? "" : ", ", v, v);
    }
  return tics.empty() ? "" : "set cbtics (" + tics + ")\n";
}

std::string series_style(std::size_t i) {
  const std::size_t n = sizeof(kLineColours) / sizeof(*kLineColours);
  return fmt::format("lc rgb '{}' dt {} pt {} lw {:.1f} ps {:.1f}", kLineColours[i % n], 1 + static_cast<int>(i % 4),
                     kPointTypes[i % n], std::max(1.0, 3.5 - 0.8 * static_cast<double>(i)),
                     std::max(0.5, 1.1 - 0.2 * static_cast<double>(i)));
}

std::string series_colour(std::size_t i) { return kLineColours[i % (sizeof(kLineColours) / sizeof(*kLineColours))]; }

// With SSE2 two values a step in four pairs of accumulators (the scalar loop is a chain of
// dependent compares: 0.18 to 0.26 ms of a full map's 137,000 cells inside `simulate`); a value
// that is not finite counts as +inf for the minimum and -inf for the maximum. A minimum or maximum
// of 0 found as both +0 and -0 may come out with either sign.
std::pair<double, double> finite_range(MatrixRows rows) {
  double lo = INFINITY, hi = -INFINITY;
  for (const auto& r : rows) {
    const double* v = r.data();
    const std::size_t n = r.size();
    std::size_t i = 0;
#if defined(__SSE2__)
    if (n >= 8) {
      const __m128d magnitude = _mm_castsi128_pd(_mm_set1_epi64x(0x7fffffffffffffffLL));
      const __m128d largest = _mm_set1_pd(std::numeric_limits<double>::max());
      const __m128d up = _mm_set1_pd(INFINITY), down = _mm_set1_pd(-INFINITY);
      __m128d mn[4] = {up, up, up, up}, mx[4] = {down, down, down, down};
      for (; i + 8 <= n; i += 8)
        for (int j = 0; j < 4; ++j) {
          const __m128d x = _mm_loadu_pd(v + i + 2 * j);
          const __m128d finite = _mm_cmple_pd(_mm_and_pd(x, magnitude), largest);  // false for NaN and inf
          mn[j] = _mm_min_pd(mn[j], _mm_or_pd(_mm_and_pd(finite, x), _mm_andnot_pd(finite, up)));
          mx[j] = _mm_max_pd(mx[j], _mm_or_pd(_mm_and_pd(finite, x), _mm_andnot_pd(finite, down)));
        }
      const __m128d a = _mm_min_pd(_mm_min_pd(mn[0], mn[1]), _mm_min_pd(mn[2], mn[3]));
      const __m128d b = _mm_max_pd(_mm_max_pd(mx[0], mx[1]), _mm_max_pd(mx[2], mx[3]));
      lo = std::min({lo, _mm_cvtsd_f64(a), _mm_cvtsd_f64(_mm_unpackhi_pd(a, a))});
      hi = std::max({hi, _mm_cvtsd_f64(b), _mm_cvtsd_f64(_mm_unpackhi_pd(b, b))});
    }
#endif
    for (; i < n; ++i) {
      const bool finite = std::isfinite(v[i]);  // no branch on the value: a map's NaNs come in any pattern
      lo = finite && v[i] < lo ? v[i] : lo;
      hi = finite && v[i] > hi ? v[i] : hi;
    }
  }
  if (lo > hi) return {NAN, NAN};
  return {lo, hi};
}

}  // namespace rangesim::app
