// Demodulating pixel kernel against the golden front end: noise-free output (exact to rounding),
// ticking == event skipping, and noise mean / variance against the closed forms.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "golden/ls_demodulation/decision.h"
#include "golden/ls_demodulation/front_end.h"
#include "systemc/ls_demodulation/pixel_kernel.h"
#include "systemc/common/random_stream.h"
#include "tests/systemc/ls_demodulation/demod_test_helpers.h"

namespace rangesim::systemc {
namespace {

struct Point {
  double beam_A, background_A;
};
// Signal/background points across the published ranges: weak signal, nominal, strong signal on
// weak background, strong background (log compression), background only, LPF floor clipping.
const std::vector<Point> kPoints = {{7.4e-12, 1e-10}, {1.11e-10, 1e-10}, {1e-9, 1e-12},
                                    {1e-11, 1e-7},    {0.0, 1e-8},       {2e-9, 1e-6}};

// Runs one window; tick = step(1) every cycle, else jump edge to edge.
DemodPixelKernel run_window(const LsDemodulationConfig& c, const DemodWindowSchedule& s, double beam, double bg,
                            bool tick, const DemodNoiseSwitches& noise, std::uint64_t key) {
  DemodPixelKernel p(c, s);
  pcg32 rng = pixel_stream(key);
  p.reset(beam, bg, rng, noise);
  for (int guard = 0; !p.window_done(); ++guard) {
    EXPECT_LT(guard, s.window_cycles() + 1);
    p.step(tick ? 1 : p.cycles_to_edge());
  }
  return p;
}

TEST(DemodPixelKernel, ScheduleOfThePreset) {
  const auto c = test::preset_config();
  const auto s = demod_window_schedule(c);
  EXPECT_EQ(s.period_cycles, 100);
  EXPECT_EQ(s.periods, 5);
  EXPECT_EQ(s.window_cycles(), 500);
  int sum = 0;
  for (int k : s.segment_cycles) sum += k;
  EXPECT_EQ(sum, 100);
}

TEST(DemodPixelKernel, RejectsEdgesBetweenClockEdges) {
  auto c = test::preset_config();
  c.modulation.frequency_Hz = 30e3;  // 333.3 cycles per period
  EXPECT_THROW(demod_window_schedule(c), std::invalid_argument);
  c = test::preset_config();
  c.correlator.reference_duty_cycle = 0.503;  // MPY edge at 50.3 cycles
  EXPECT_THROW(demod_window_schedule(c), std::invalid_argument);
}

TEST(DemodPixelKernel, NoiseFreeReproducesGoldenCorrelator) {
  const auto c = test::preset_config();
  const auto s = demod_window_schedule(c);
  for (const auto& pt : kPoints) {
    const auto g =
        golden::correlate_periodic(c, golden::pixel_segments(c, pt.beam_A, pt.background_A), c.correlator.cycles);
    for (bool tick : {false, true}) {
      const auto p = run_window(c, s, pt.beam_A, pt.background_A, tick, DemodNoiseSwitches::none(), 1);
      const double tol = 1e-10 + 1e-9 * std::max(std::fabs(g.plus_V), std::fabs(g.minus_V));
      EXPECT_NEAR(p.plus_V(), g.plus_V, tol) << pt.beam_A << " " << pt.background_A << " tick " << tick;
      EXPECT_NEAR(p.minus_V(), g.minus_V, tol) << pt.beam_A << " " << pt.background_A << " tick " << tick;
      EXPECT_NEAR(p.diff_V(), g.diff_V, tol);
      EXPECT_NEAR(p.lpf_A(), g.lpf_end_A, 1e-9 * g.lpf_end_A + 1e-24);
      EXPECT_EQ(p.diff_V() >= c.comparator.threshold_V, g.diff_V >= c.comparator.threshold_V);
    }
  }
}

TEST(DemodPixelKernel, EventSkippingEqualsTickingWithNoise) {
  const auto c = test::preset_config();
  const auto s = demod_window_schedule(c);
  for (const auto& pt : kPoints) {
    const auto a = run_window(c, s, pt.beam_A, pt.background_A, false, DemodNoiseSwitches{}, 77);
    const auto b = run_window(c, s, pt.beam_A, pt.background_A, true, DemodNoiseSwitches{}, 77);
    EXPECT_NEAR(a.diff_V(), b.diff_V(), 1e-8);  // per-piece vs whole-segment quadrature
  }
}

// Mean and variance of D over independent windows against golden diff_V and
// shot_var_V2 + kTC (+ fixed pattern): 4000 samples, bounds at ~5 standard errors.
TEST(DemodPixelKernel, NoiseMomentsMatchClosedForms) {
  auto c = test::preset_config();
  c.noise.fixed_pattern_rms_V = 0.2e-3;
  const auto s = demod_window_schedule(c);
  const int n = 4000;
  for (const auto& pt : {Point{1.11e-10, 1e-10}, Point{1e-10, 1e-7}, Point{0.0, 1e-6}}) {
    const auto d = golden::pixel_decision(c, pt.beam_A, pt.background_A);
    const double var_g = d.sigma_independent_V * d.sigma_independent_V;
    double sum = 0, sum2 = 0;
    for (int i = 0; i < n; ++i) {
      const double v = run_window(c, s, pt.beam_A, pt.background_A, false, DemodNoiseSwitches{},
                                  pixel_stream_key(5, static_cast<std::uint64_t>(i), 0, 0))
                           .diff_V();
      sum += v;
      sum2 += v * v;
    }
    const double mean = sum / n, var = (sum2 - n * mean * mean) / (n - 1);
    EXPECT_NEAR(mean, d.out.diff_V, 5 * std::sqrt(var_g / n)) << pt.background_A;
    EXPECT_NEAR(var / var_g, 1.0, 5 * std::sqrt(2.0 / (n - 1))) << pt.background_A << " shot " << d.out.shot_var_V2;
  }
}

}  // namespace
}  // namespace rangesim::systemc
