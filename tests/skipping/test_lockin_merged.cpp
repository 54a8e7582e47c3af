// tof-lockin's merged draws (config simulation.merged_draws, systemc/tof_lockin/frame_draw.h):
// an aggregated frame drawn as one Poisson count per tap (frame and offset charge) and one normal
// (kTC and read noise) where V_sat cannot be reached, against the same frames with every term
// drawn apart (today's path, merged_draws = false). Stated test, different seeds, for each tap's
// ADC input over the LED frames and for the range: means and variances within 5 standard errors,
// two-sample KS p >= 0.001 (app/bench/bench_stats.h), with the count from alias tables and from
// PTRS, and near saturation (kTC and read noise apart). The same test rejects 3 % more signal.
// The saturation bound that allows the joined normal is checked against the exact tail.
#include <gtest/gtest.h>

#include <cmath>

#include "../systemc/tof_lockin/lockin_sc_test_util.h"
#include "app/bench/bench_stats.h"
#include "comparison_text.h"
#include "lockin_samples.h"
#include "golden/tof_lockin/tap_charge.h"

namespace rangesim::systemc::lockin {
namespace {

using app::bench::compare_samples;
using app::bench::describe;
using app::bench::TwoSampleComparison;

using test::Samples;

struct Run {
  bool merged = true, tables = true;
  double signal_A = 3e-10, background_A = 1e-10, distance_m = 2.0;
  std::uint64_t seed = 1;
};

Samples run(const Run& r) {
  TofLockinConfig cfg = test::edited_config({{"pixel", "rows", "1"}});
  cfg.simulation.merged_draws = r.merged;
  LockinSimOptions o;
  o.aggregate = true, o.seed = r.seed;
  o.poisson_tables = r.tables ? PoissonTables::Always : PoissonTables::Never;
  const int columns = 128;
  const long long frames = 80;  // 40 range maps: 5120 LED samples per tap
  TofLockinSensorKernel k(cfg, o, 1, columns, test::uniform(columns, r.signal_A, r.background_A, r.distance_m), frames);
  k.run();
  EXPECT_EQ(k.merged_draws(), r.merged);
  return test::led_samples(k, columns);
}

void expect_indistinguishable(const Samples& a, const Samples& b, bool ranges = true) {
  for (int t = 0; t < 2; ++t) {
    const TwoSampleComparison c = compare_samples(a.tap[t], b.tap[t]);
    EXPECT_TRUE(c.indistinguishable()) << "tap " << t + 1 << ": " << describe(c);
    EXPECT_GT(c.var_a, 0.0);
  }
  if (!ranges) return;
  const TwoSampleComparison r = compare_samples(a.range, b.range);
  EXPECT_TRUE(r.indistinguishable()) << "range: " << describe(r);
}

TEST(LockinMergedDraws, StatisticallyIdenticalToSeparateDrawsWithTables) {
  expect_indistinguishable(run({true, true, 3e-10, 1e-10, 2.0, 21}), run({false, true, 3e-10, 1e-10, 2.0, 22}));
}

TEST(LockinMergedDraws, StatisticallyIdenticalToSeparateDrawsWithPtrs) {
  expect_indistinguishable(run({true, false, 3e-10, 1e-10, 9.0, 23}), run({false, false, 3e-10, 1e-10, 9.0, 24}));
}

// FD1 close to V_sat (1.44 V of 1.5 V): the bound keeps kTC and read noise apart, the clip acts.
TEST(LockinMergedDraws, StatisticallyIdenticalNearSaturation) {
  const TofLockinConfig cfg = test::edited_config({});
  const golden::FrameCharge c = golden::frame_charge(cfg, 2.85e-9, 1e-10, golden::round_trip_delay_s(0.3));
  ASSERT_GT(golden::tap_sample(cfg, 0, c.total_e(0)).fd_swing_V, 1.4);
  const double offset_e =
      cfg.pixel.offset_voltage_V / (golden::volts_per_electron(cfg, 0) / cfg.pixel.source_follower_gain);
  EXPECT_TRUE(swing_may_saturate(cfg, 0, c.total_e(0) + offset_e, offset_e));
  expect_indistinguishable(run({true, true, 2.85e-9, 1e-10, 0.3, 25}), run({false, true, 2.85e-9, 1e-10, 0.3, 26}),
                           false);
}

TEST(LockinMergedDraws, TestRejectsThreePercentMoreSignal) {
  const Samples a = run({true, true, 3.09e-10, 1e-10, 2.0, 27}), b = run({false, true, 3e-10, 1e-10, 2.0, 28});
  EXPECT_FALSE(compare_samples(a.tap[0], b.tap[0]).indistinguishable());
}

// A pixel's merged draws depend on its own key and law only: the same pixel alone and inside a
// row of others, same seed, gives the same codes bit for bit; and the same seed repeats them.
TEST(LockinMergedDraws, PixelBitsDependOnItsKeyAlone) {
  const TofLockinConfig cfg = test::edited_config({{"pixel", "rows", "1"}});
  LockinSimOptions o;
  o.aggregate = true, o.seed = 5;
  std::vector<LockinPixelStimulus> row = test::uniform(16, 3e-10, 1e-10, 2.0);
  row[3].signal_A = 1e-10;
  TofLockinSensorKernel all(cfg, o, 1, 16, row, 4), again(cfg, o, 1, 16, row, 4), one(cfg, o, 1, 1, {row[0]}, 4);
  all.run(), again.run(), one.run();
  for (long long f = 0; f < 4; ++f)
    for (int k = 0; k < 2; ++k) {
      EXPECT_EQ(all.code(f, 0, 0, k), one.code(f, 0, 0, k));
      for (int c = 0; c < 16; ++c) EXPECT_EQ(all.code(f, 0, c, k), again.code(f, 0, c, k));
    }
}

// Without noise nothing is drawn: the switch changes no bit.
TEST(LockinMergedDraws, NoiseFreeFramesBitIdentical) {
  TofLockinConfig on = test::edited_config({{"pixel", "rows", "1"}}), off = on;
  off.simulation.merged_draws = false;
  LockinSimOptions o;
  o.noise = false, o.aggregate = true;
  const auto stim = test::uniform(8, 3e-10, 1e-10, 2.0);
  TofLockinSensorKernel a(on, o, 1, 8, stim, 4), b(off, o, 1, 8, stim, 4);
  a.run(), b.run();
  for (long long f = 0; f < 4; ++f)
    for (int c = 0; c < 8; ++c)
      for (int k = 0; k < 2; ++k) EXPECT_EQ(a.adc_input_V(f, 0, c, k), b.adc_input_V(f, 0, c, k));
}

// log of the upper normal tail Q(z), accurate far out.
long double log_q(long double z) {
  if (z < 5) return std::log(0.5L * std::erfc(z / std::sqrt(2.0L)));
  // Q(z) = phi(z) / z (1 - 1/z^2 + 3/z^4 - ...), asymptotic.
  const long double z2 = z * z;
  return -z2 / 2 - std::log(z * std::sqrt(2 * std::acos(-1.0L))) +
         std::log1p(-1 / z2 + 3 / (z2 * z2) - 15 / (z2 * z2 * z2));
}

// P(FD swing >= V_sat) summed exactly over the count (log-sum-exp in long double).
long double saturation_probability(const TofLockinConfig& cfg, double count_mean_e, double offset_e) {
  const long double g = golden::volts_per_electron(cfg, 0) / cfg.pixel.source_follower_gain;
  const long double ktc = golden::ktc_noise_V(cfg, 0) / cfg.pixel.source_follower_gain, mu = count_mean_e;
  long double best = -1e300L, acc = 0;
  std::vector<long double> terms;
  const long long k0 = static_cast<long long>(mu), span = static_cast<long long>(60 * std::sqrt(mu)) + 100;
  for (long long n = std::max(0LL, k0 - span); n <= k0 + span; ++n) {
    const long double swing = (n - offset_e) * g + cfg.pixel.offset_voltage_V;
    const long double lp = -mu + n * std::log(mu) - std::lgamma(static_cast<long double>(n) + 1);
    const long double t = lp + log_q((cfg.pixel.saturation_voltage_V - swing) / ktc);
    terms.push_back(t);
    best = std::max(best, t);
  }
  for (long double t : terms) acc += std::exp(t - best);
  return std::exp(best + std::log(acc));
}

TEST(LockinMergedDraws, SaturationBoundBelowTwoToTheMinusSixty) {
  const TofLockinConfig cfg = test::edited_config({});
  const double offset_e =
      cfg.pixel.offset_voltage_V / (golden::volts_per_electron(cfg, 0) / cfg.pixel.source_follower_gain);
  // The largest count mean the bound clears (bisection on the flag).
  double lo = offset_e, hi = 2e5;
  ASSERT_FALSE(swing_may_saturate(cfg, 0, lo, offset_e));
  ASSERT_TRUE(swing_may_saturate(cfg, 0, hi, offset_e));
  for (int i = 0; i < 60; ++i) {
    const double mid = (lo + hi) / 2;
    (swing_may_saturate(cfg, 0, mid, offset_e) ? hi : lo) = mid;
  }
  const long double p = saturation_probability(cfg, lo, offset_e);
  EXPECT_LT(p, std::ldexp(1.0L, -60)) << "mean " << lo << " e-";
  // And the bound is not loose by much: two count sigmas more charge than it clears reach 1e-20.
  EXPECT_GT(saturation_probability(cfg, lo + 2 * std::sqrt(lo), offset_e), 1e-20L);
}

}  // namespace
}  // namespace rangesim::systemc::lockin
