#include "golden/ls_conventional/multisampling.h"

#include <algorithm>
#include <cmath>

#include "golden/common/pixel.h"

namespace rangesim::golden {
namespace {

// Activated pixel range [l, r] of a half-width around x0, clamped to the row; false if empty.
bool activated_range(const RowModel& row, double x0, double h, int& l, int& r) {
  if (h < 0) return false;
  const double lo = std::ceil(x0 - h), hi = std::floor(x0 + h);
  l = lo < 0 ? 0 : static_cast<int>(std::min<double>(lo, row.columns));
  r = hi > row.columns - 1 ? row.columns - 1 : static_cast<int>(std::max<double>(hi, -1));
  return l <= r;
}

}  // namespace

CentreEstimate sampling_estimate(const RowModel& row, double x0_px, int k) {
  const std::vector<double>& h = row.half_width_px[k - 1];
  int l, r;
  if (!activated_range(row, x0_px, h[0], l, r)) return {};
  if (row.quantiser.bits == 1) return {true, 0.5 * (l + r)};
  // Code of pixel i = number of levels whose half-width covers |x_i - x0| (h non-increasing in m).
  double sw = 0, swx = 0;
  for (int i = l; i <= r; ++i) {
    const double d = std::fabs(i - x0_px);
    const int code =
        static_cast<int>(std::partition_point(h.begin(), h.end(), [d](double hm) { return hm >= d; }) - h.begin());
    sw += code;
    swx += code * static_cast<double>(i);
  }
  if (!(sw > 0)) return {};
  return {true, swx / sw};
}

CentreEstimate noise_free_estimate(const RowModel& row, double x0_px) {
  double sum = 0;
  int n = 0;
  for (int k = 1; k <= row.samplings; ++k) {
    const CentreEstimate c = sampling_estimate(row, x0_px, k);
    if (c.detected) {
      sum += c.centre_px;
      ++n;
    }
  }
  if (n == 0) return {};
  return {true, sum / n};
}

CentreEstimate direct_estimate(const RowModel& row, double x0_px) {
  std::vector<double> x(row.columns);
  for (int i = 0; i < row.columns; ++i) x[i] = i;
  std::vector<CentreEstimate> per;
  for (int k = 1; k <= row.samplings; ++k) {
    std::vector<double> codes(row.columns);
    std::vector<bool> active(row.columns);
    for (int i = 0; i < row.columns; ++i) {
      const double v = output_voltage_V(row.cfg.pixel, row_pixel_swing_V(row, i, x0_px, k));
      codes[i] = quantise(row.quantiser, v);
      active[i] = codes[i] > 0;
    }
    per.push_back(row.quantiser.bits == 1 ? edge_centre(x, active) : weighted_centroid(x, codes));
  }
  return mean_of_detections(per);
}

std::vector<double> estimate_breakpoints(const RowModel& row, double lo_px, double hi_px) {
  std::vector<double> b{lo_px, hi_px};
  for (const auto& hk : row.half_width_px)
    for (double h : hk) {
      if (!(h >= 0) || std::isinf(h)) continue;
      for (double s : {-1.0, 1.0}) {
        // x0 = j + s h crosses pixel j's level.
        for (double j = std::ceil(lo_px - s * h); j + s * h <= hi_px; j += 1) {
          const double x = j + s * h;
          if (x > lo_px && x < hi_px) b.push_back(x);
        }
      }
    }
  std::sort(b.begin(), b.end());
  b.erase(std::unique(b.begin(), b.end()), b.end());
  return b;
}

QuantisationError quantisation_error(const RowModel& row) {
  const double lo = row.centre_pixel - 0.5, hi = row.centre_pixel + 0.5;
  const std::vector<double> b = estimate_breakpoints(row, lo, hi);
  QuantisationError q;
  double len_detected = 0, sum_sq = 0;
  bool have_prev = false;
  double prev = 0, first = 0;
  bool have_first = false, all_detected = true;
  int jumps = 0;
  for (size_t s = 0; s + 1 < b.size(); ++s) {
    const double xa = b[s], xb = b[s + 1];
    if (!(xb > xa)) continue;
    const CentreEstimate c = noise_free_estimate(row, 0.5 * (xa + xb));
    ++q.segments;
    if (!c.detected) {
      have_prev = false;
      all_detected = false;
      continue;
    }
    if (!have_first) first = c.centre_px, have_first = true;
    // integral over [xa, xb] of (xhat - x)^2 dx
    const double ea = c.centre_px - xa, eb = c.centre_px - xb;
    sum_sq += (ea * ea * ea - eb * eb * eb) / 3.0;
    len_detected += xb - xa;
    q.worst_px = std::max({q.worst_px, std::fabs(ea), std::fabs(eb)});
    if (have_prev && c.centre_px != prev) {
      q.largest_step_px = std::max(q.largest_step_px, std::fabs(c.centre_px - prev));
      ++jumps;
    }
    prev = c.centre_px;
    have_prev = true;
  }
  q.detected_fraction = len_detected / (hi - lo);
  if (len_detected > 0) q.rms_px = std::sqrt(sum_sq / len_detected);
  q.equivalent_step_px = std::sqrt(12.0) * q.rms_px;
  // xhat(x0 + 1) = xhat(x0) + 1, so the estimate rises by 1 px per pixel of travel; the jump
  // between this period's last segment and the next period's first closes the count.
  if (all_detected && have_first && prev != first + 1.0) {
    q.largest_step_px = std::max(q.largest_step_px, std::fabs(first + 1.0 - prev));
    ++jumps;
  }
  q.resolution_px = all_detected && jumps > 0 ? 1.0 / jumps : q.equivalent_step_px;
  return q;
}

}  // namespace rangesim::golden
