#include "systemc/tof_lockin/normal_ziggurat.h"

#include <cmath>
#include <stdexcept>

namespace rangesim::systemc::lockin {

namespace {

using LD = long double;

// Area of each region for the base edge r: the strip r f(r) plus the tail beyond r.
LD region_area(LD r) {
  return r * std::exp(-r * r / 2) + std::sqrt(std::acos(LD(-1)) / 2) * std::erfc(r / std::sqrt(LD(2)));
}

// Walks the regions up from x_1 = r; returns f(x_255) + v / x_255 - 1 (0 when region 255 closes
// exactly at the top), or +1 when the regions reach the top early (r too small).
LD closure(LD r, LD* x) {
  const LD v = region_area(r);
  x[0] = v / std::exp(-r * r / 2), x[1] = r;
  for (int i = 1; i < NormalZiggurat::kRegions - 1; ++i) {
    const LD y = std::exp(-x[i] * x[i] / 2) + v / x[i];
    if (y >= 1) return 1;
    x[i + 1] = std::sqrt(-2 * std::log(y));
  }
  const int last = NormalZiggurat::kRegions - 1;
  return std::exp(-x[last] * x[last] / 2) + v / x[last] - 1;
}

}  // namespace

NormalZiggurat::NormalZiggurat() {
  LD x[kRegions + 1];
  // Bracketed secant (regula falsi, Illinois step) on closure(r), which falls through 0 between
  // 3.6 (regions reach the top early) and 3.7 (they do not reach it): ~10 walks of the regions.
  LD lo = 3.6L, hi = 3.7L, f_lo = closure(lo, x), f_hi = closure(hi, x);
  int side = 0;
  for (int it = 0; it < 100 && hi - lo > 1e-18L; ++it) {
    const LD r = (lo * f_hi - hi * f_lo) / (f_hi - f_lo), f = closure(r, x);
    if (f > 0) {
      lo = r, f_lo = f;
      if (side == 1) f_hi /= 2;
      side = 1;
    } else {
      hi = r, f_hi = f;
      if (side == -1) f_lo /= 2;
      side = -1;
    }
    if (f == 0) lo = hi = r;
  }
  if (std::fabs(static_cast<double>(closure(hi, x))) > 1e-12) throw std::logic_error("ziggurat: regions do not close");
  x[kRegions] = 0;
  r_ = static_cast<double>(hi);
  v_ = static_cast<double>(region_area(hi));
  for (int i = 0; i <= kRegions; ++i) {
    x_[i] = static_cast<double>(x[i]);
    f_[i] = static_cast<double>(std::exp(-x[i] * x[i] / 2));
  }
  for (int i = 0; i < kRegions; ++i) width_[i] = static_cast<double>(x[i] / 4503599627370496.0L);  // / 2^52
}

}  // namespace rangesim::systemc::lockin
