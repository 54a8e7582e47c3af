// ls-demodulation aggregation (DemodKernelOptions::aggregate: the N identical correlation periods
// of a window in one jump, golden::correlate_periodic's swings and one shot-noise draw per
// integrator of the summed variance) against the same frames stepped period by period.
//   - noise-free: identical cycles, phases, activations and positions; D equal to 1e-12 relative
//     (+ 1e-14 V where D cancels);
//   - with noise: D of every pixel, means and variances within 5 standard errors and a two-sample
//     Kolmogorov-Smirnov p >= 0.001 at fixed seeds (app/bench/bench_stats.h); the same test must
//     reject a run whose beam is 3% stronger;
//   - a window of 1e9 periods (1e11 clock cycles) runs in the kernel in bounded memory and time.
#include <gtest/gtest.h>
#include <sys/resource.h>

#include <chrono>
#include <cmath>
#include <cstdio>

#include "../systemc/ls_demodulation/demod_test_helpers.h"
#include "app/bench/bench_stats.h"
#include "comparison_text.h"
#include "golden/ls_demodulation/front_end.h"

namespace rangesim::systemc {
namespace {

using app::bench::compare_samples;
using app::bench::describe;
using app::bench::TwoSampleComparison;

// The preset's physics on `rows` x `columns` pixels with N = `periods` correlation periods.
LsDemodulationConfig config(int rows, int columns, int periods) {
  LsDemodulationConfig c = test::small_config(rows, columns);
  c.correlator.cycles = periods;
  c.pixel.integration_time_s = periods / c.modulation.frequency_Hz;
  return c;
}

DemodStimulusSource uniform(const LsDemodulationConfig& c, double beam_A, double background_A) {
  return [=](std::uint64_t, DemodStimulus& s) {
    s.beam_A.assign(static_cast<std::size_t>(c.pixel.rows) * c.pixel.columns, beam_A);
    s.background_A.assign(s.beam_A.size(), background_A);
  };
}

DemodRunResult run(const LsDemodulationConfig& c, bool aggregate, const DemodStimulusSource& src, long long frames,
                   std::uint64_t seed, bool noise) {
  DemodKernelOptions o;
  o.aggregate = aggregate;
  o.seed = seed;
  o.keep_analogue = true;
  if (!noise) o.noise = DemodNoiseSwitches::none();
  return run_demod_kernel(c, o, src, frames);
}

std::vector<double> all_diff_V(const DemodRunResult& r) {
  std::vector<double> d;
  for (const auto& f : r.frames) d.insert(d.end(), f.diff_V.begin(), f.diff_V.end());
  return d;
}

TEST(DemodAggregation, NoiseFreeEqualsPerPeriod) {
  LsDemodulationConfig c = config(3, 20, 37);
  c.grid.detections = 2;
  const auto src = test::spot_source(c, 3e-11, 1e-9, 6.3, 0.41, 1.7);
  const DemodRunResult a = run(c, true, src, 3, 5, false), p = run(c, false, src, 3, 5, false);
  ASSERT_EQ(a.frames.size(), p.frames.size());
  EXPECT_EQ(a.cycles, p.cycles);
  int activated = 0;
  for (std::size_t f = 0; f < a.frames.size(); ++f) {
    EXPECT_EQ(a.frames[f].cycles, p.frames[f].cycles);
    EXPECT_EQ(a.frames[f].phase_cycles, p.frames[f].phase_cycles);
    EXPECT_EQ(a.frames[f].rows, p.frames[f].rows);
    EXPECT_EQ(a.frames[f].activations, p.frames[f].activations);
    for (const auto& act : a.frames[f].activations) activated += act.any() ? 1 : 0;
    ASSERT_EQ(a.frames[f].diff_V.size(), p.frames[f].diff_V.size());
    // N x one period (golden) against N periods summed one by one: rounding of the sum, and the
    // LPF state carried from period to period instead of the closed-form periodic start. Off the
    // spot D = V+ - V- cancels swings of ~1e-2 V: an absolute 1e-14 V (1e-12 of the threshold).
    for (std::size_t i = 0; i < a.frames[f].diff_V.size(); ++i)
      EXPECT_NEAR(a.frames[f].diff_V[i], p.frames[f].diff_V[i], 1e-12 * std::fabs(p.frames[f].diff_V[i]) + 1e-14);
  }
  EXPECT_GT(activated, 0);  // the decisions compared are not all "no"
}

// 6000 D samples per path: 30 frames of 4 x 50 pixels under one uniform beam, near the threshold
// (SNR ~5, shot noise dominant), N = 20 periods.
std::vector<double> noisy_samples(bool aggregate, double beam_A, std::uint64_t seed) {
  const LsDemodulationConfig c = config(4, 50, 20);
  return all_diff_V(run(c, aggregate, uniform(c, beam_A, 1e-10), 30, seed, true));
}

TEST(DemodAggregation, StatisticallyIdenticalToPerPeriod) {
  const std::vector<double> agg = noisy_samples(true, 3e-12, 61), per = noisy_samples(false, 3e-12, 62);
  ASSERT_EQ(agg.size(), 6000u);
  ASSERT_EQ(per.size(), agg.size());
  const TwoSampleComparison c = compare_samples(agg, per);
  std::printf("aggregated vs per period: %s\n", describe(c).c_str());
  EXPECT_TRUE(c.indistinguishable()) << describe(c);
  EXPECT_GT(c.var_a, 0.0);  // noise really on
}

TEST(DemodAggregation, TestRejectsThreePercentMoreSignal) {
  const std::vector<double> agg = noisy_samples(true, 3e-12, 61), more = noisy_samples(true, 3.09e-12, 63);
  const TwoSampleComparison c = compare_samples(agg, more);
  std::printf("aggregated vs 3%% more beam: %s\n", describe(c).c_str());
  EXPECT_FALSE(c.indistinguishable()) << describe(c);
}

long max_rss_kB() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  return u.ru_maxrss;
}

// N = 1e9 correlation periods (1e11 clock cycles) per window. Stepped period by period the window
// takes ~1e9 x S log integrals (hours); the old kernel also held N x S segments (~100 GB). Aggregated:
// one jump, memory independent of N (the time is bounded by the ctest timeout; measured in the log).
TEST(DemodAggregation, BillionPeriodWindowInBoundedMemory) {
  const LsDemodulationConfig c = config(2, 16, 1000000000);
  const long rss0 = max_rss_kB();
  const auto t0 = std::chrono::steady_clock::now();
  const DemodRunResult r = run(c, true, test::spot_source(c, 1e-12, 1e-10, 7.0), 1, 9, false);
  const double wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const long grown_kB = max_rss_kB() - rss0;
  RecordProperty("wall_s", std::to_string(wall_s));
  RecordProperty("max_rss_growth_kB", std::to_string(grown_kB));
  std::printf("1e9-period window, 2 x 16 pixels: %.3g s, max RSS grew by %ld kB\n", wall_s, grown_kB);
  ASSERT_EQ(r.frames.size(), 1u);
  const long long window = 1000000000LL * 100;  // N x clock / f0
  EXPECT_EQ(r.frames[0].phase_cycles[0], window);
  EXPECT_EQ(r.frames[0].cycles, window + 1 + 2LL * c.readout.row_cycles);
  EXPECT_LT(grown_kB, 16 * 1024);
  // D is golden's aggregated window (1e9 x one period) at the spot peak.
  const golden::CorrelatorOutput g =
      golden::correlate_periodic(c, golden::pixel_segments(c, 1e-12, 1e-10), c.correlator.cycles);
  EXPECT_NEAR(r.frames[0].diff_V[7], g.diff_V, 1e-12 * std::fabs(g.diff_V));
  EXPECT_GT(r.frames[0].rows_detected(), 0);
}

}  // namespace
}  // namespace rangesim::systemc
