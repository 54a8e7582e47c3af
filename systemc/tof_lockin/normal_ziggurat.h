#pragma once
// Standard normal variates by the ziggurat method (G. Marsaglia, W. W. Tsang, "The ziggurat method
// for generating random variables", J. Statistical Software 5(8), 2000), 256 regions of equal
// area under f(x) = exp(-x^2 / 2), one 64-bit word per try (J. A. Doornik, "An improved ziggurat
// method to generate normal random samples", 2005: the region index, the sign and the abscissa
// from disjoint bits of the word, so they are independent).
//
// Region 0 is the base strip [0, r] x [0, f(r)] with the tail x > r; region i >= 1 is the
// rectangle [0, x_i] x [f(x_i), f(x_{i+1})], x_1 = r > x_2 > ... > x_256 = 0. A try picks a region
// i and x = u w_i (w_0 = v / f(r), w_i = x_i): if x < x_{i+1} the point is under the curve
// whatever its height (about 99 % of the tries: one multiply and one compare); otherwise region 0
// draws from the tail (Marsaglia's exponential method, exact) and region i >= 1 tests a uniform
// height against f(x) (the wedge). The method is exact: it samples the area under f uniformly;
// r is solved at start-up so that the regions close at x_256 = 0 (to 1e-12 of the area)
// (NormalZiggurat.* in tests/skipping/test_lockin_draws.cpp: moments, KS and tails against the
// normal law, and the test's power against a 3 % wider law).
#include <cmath>
#include <cstdint>

namespace rangesim::systemc::lockin {

class NormalZiggurat {
 public:
  static constexpr int kRegions = 256;
  // The tables, built once (thread-safe static).
  static const NormalZiggurat& tables() {
    static const NormalZiggurat z;
    return z;
  }

  // One standard normal from a stream with next() -> 64-bit word.
  template <class Stream>
  double operator()(Stream& s) const {
    for (;;) {
      const std::uint64_t w = s.next();
      const int i = static_cast<int>(w & 0xff);
      const double sign = (w & 0x100) ? -1.0 : 1.0;
      const std::uint64_t m = w >> 12;  // 52 bits
      const double x = static_cast<double>(m) * width_[i];
      if (x < x_[i + 1]) return sign * x;  // under the curve at any height
      if (i == 0) return sign * tail(s);
      // Wedge: a uniform height in [f(x_i), f(x_{i+1})] against f(x).
      const double y = f_[i] + (f_[i + 1] - f_[i]) * unit(s.next());
      if (y < std::exp(-0.5 * x * x)) return sign * x;
    }
  }

  double r() const { return r_; }
  double area() const { return v_; }

 private:
  NormalZiggurat();
  template <class Stream>
  double tail(Stream& s) const {
    for (;;) {
      const double x = -std::log(unit(s.next())) / r_, y = -std::log(unit(s.next()));
      if (y + y > x * x) return r_ + x;
    }
  }
  static double unit(std::uint64_t w) { return (static_cast<double>(w >> 11) + 0.5) * (1.0 / 9007199254740992.0); }

  double r_ = 0, v_ = 0;
  double width_[kRegions];  // w_i / 2^52: x = m width_[i] for the 52-bit m
  double x_[kRegions + 1];  // x_i (x_[0] = w_0, x_[1] = r, x_[256] = 0)
  double f_[kRegions + 1];  // f(x_i) (f_[0] unused), f_[256] = 1
};

}  // namespace rangesim::systemc::lockin
