#pragma once
// Shared by the proofs of ls-conventional's exact activation sampling and its switches
// (test_exact_activation.cpp, test_certain_intervals.cpp, test_inversion_draw.cpp): the preset,
// the independent tail sum, the representative rows and the first-firing battery.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "app/bench/bench_stats.h"
#include "core/ls_conventional/config.h"
#include "core/preset.h"
#include "golden/common/pixel.h"
#include "systemc/ls_conventional/activation_sampler.h"
#include "systemc/ls_conventional/pixel_array_kernel.h"
#include "tests/systemc/sensor_test_helpers.h"

namespace exact_test {

namespace rs = rangesim::systemc;
using rangesim::LsConventionalConfig;
using rangesim::app::bench::compare_samples;

inline LsConventionalConfig preset() {
  return rangesim::ls_conventional_from_params(
      rangesim::load_preset_file(std::string(RANGESIM_PRESET_DIR) + "/ls-conventional.toml"));
}

inline rs::ActivationModel model_of(const LsConventionalConfig& c, bool shot = true, bool ktc = true,
                                    bool read = true) {
  rs::ActivationModel m;
  m.shot = shot;
  m.ktc_V = ktc ? rangesim::golden::ktc_noise_V(c.pixel) : 0.0;
  m.read_V = read ? c.pixel.read_noise_V : 0.0;
  m.electrons_per_V = rangesim::golden::electrons_per_volt(c.pixel);
  m.gain = c.pixel.source_follower_gain;
  m.saturation_V = c.pixel.saturation_voltage_V;
  m.samplings = c.multisampling.samplings;
  return m;
}

// P(n + s Z >= t) (upper) or P(n + s Z < t), n ~ Poisson(lambda): every count up to far beyond the
// mass, long double, no cuts: independent of golden::activation_probability.
inline long double true_tail(double lambda, double t, double s, bool upper) {
  const long double l = lambda, sq2 = std::sqrt(2.0L);
  const long double nmax = l + 60 * std::sqrt(l) + 200;
  long double sum = 0;
  for (long double n = 0; n <= nmax; n += 1) {
    const long double pmf = l > 0 ? std::exp(n * std::log(l) - l - std::lgamma(n + 1)) : (n == 0 ? 1.0L : 0.0L);
    long double side;
    if (s > 0) {
      side = 0.5L * std::erfc((upper ? (t - n) : (n - t)) / (s * sq2));
    } else {
      side = upper ? (n >= t ? 1 : 0) : (n < t ? 1 : 0);
    }
    sum += pmf * side;
  }
  return sum;
}

// The representative rows: the spot centre steps by 1/R px from row to row, so the pixels' mean
// swings cover the thresholds of every sampling.
struct SteppedSpot {
  rs::RowIllumination in;
  void operator()(std::uint64_t, rs::FrameStimulus& out) const {
    for (std::size_t r = 0; r < out.rows.size(); ++r) {
      out.rows[r] = in;
      out.rows[r].centre_px += static_cast<double>(r) / static_cast<double>(out.rows.size());
    }
  }
};

// First firing sampling (N + 1: never) of every pixel, per frame, run through the kernel.
inline std::vector<std::vector<double>> first_firings(LsConventionalConfig c, bool exact, std::uint64_t seed,
                                                      int frames, const rs::RowIllumination& in,
                                                      rs::PixelNoiseConfig noise = {}) {
  c.simulation.exact_activation_sampling = exact;
  rs::PixelArrayOptions o;
  o.seed = seed;
  o.noise = noise;
  rs::PixelArrayKernel px(c, o, SteppedSpot{in});
  const int N = c.multisampling.samplings, C = c.pixel.columns, R = c.pixel.rows;
  std::vector<std::vector<double>> k(static_cast<std::size_t>(C * R));
  std::vector<double> first(static_cast<std::size_t>(C * R));
  for (int f = 0; f < frames; ++f) {
    px.reset_frame(static_cast<std::uint64_t>(f));
    std::fill(first.begin(), first.end(), N + 1);
    for (int s = 1; s <= N; ++s) {
      px.sample(s);
      for (int r = 0; r < R; ++r)
        for (int i = 0; i < C; ++i) {
          double& x = first[static_cast<std::size_t>(r * C + i)];
          if (px.row(r).test(i) && x > N) x = s;
        }
    }
    for (std::size_t p = 0; p < first.size(); ++p) k[p].push_back(first[p]);
  }
  return k;
}

inline bool constant(const std::vector<double>& v) {
  for (double x : v)
    if (x != v.front()) return false;
  return true;
}

// The battery on every pixel whose first firing is random in either sample; returns how many it
// compared, and whether all passed.
inline bool all_indistinguishable(const std::vector<std::vector<double>>& a, const std::vector<std::vector<double>>& b,
                                  int& compared, double& worst_mean_z) {
  bool ok = true;
  compared = 0;
  worst_mean_z = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    if (constant(a[i]) && constant(b[i])) {
      ok = ok && a[i].front() == b[i].front();
      continue;
    }
    const auto c = compare_samples(a[i], b[i]);
    ++compared;
    worst_mean_z = std::max(worst_mean_z, std::fabs(c.mean_z));
    ok = ok && c.indistinguishable();
  }
  return ok;
}

inline LsConventionalConfig stepped_rows() { return rs::test::small_config(8, 16, 4); }

inline rs::RowIllumination representative() {
  // 30 mV peak over 10 mV background (threshold 10 mV above it): pixels from always firing at the
  // first sampling through every sampling to never, the spot at 8 positions across a pixel.
  rs::RowIllumination in;
  in.signal_V = 0.03;
  in.background_V = 0.01;
  in.centre_px = 7.3;
  return in;
}

}  // namespace exact_test
