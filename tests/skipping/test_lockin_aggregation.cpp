// tof-lockin aggregation (LockinSimOptions::aggregate: the N_acc identical gate periods of a frame
// as one Poisson draw of the total mean per tap) against the same frames clocked cycle by cycle
// (event_skipping off). Stated test, at fixed seeds, for each tap's ADC input and for the range:
// means and variances within 5 standard errors and a two-sample Kolmogorov-Smirnov p >= 0.001
// (app/bench/bench_stats.h). The same test must reject a run whose signal is 3% higher.
#include <gtest/gtest.h>

#include "../systemc/tof_lockin/lockin_sc_test_util.h"
#include "app/bench/bench_stats.h"
#include "comparison_text.h"
#include "lockin_samples.h"

namespace rangesim::systemc::lockin {
namespace {

using app::bench::compare_samples;
using app::bench::describe;
using app::bench::TwoSampleComparison;

using test::Samples;

Samples run(const TofLockinConfig& cfg, bool aggregated, double signal_A, std::uint64_t seed) {
  LockinSimOptions o;
  o.event_skipping = aggregated;
  o.aggregate = aggregated;
  o.seed = seed;
  const int columns = 64;
  const long long frames = 60;  // 30 range maps (LED + ambient frame each)
  TofLockinSensorKernel k(cfg, o, 1, columns,
                          std::vector<LockinPixelStimulus>(columns, {signal_A, 1e-10, 2 * 2.0 / 299792458.0}), frames);
  k.run();
  return test::led_samples(k, columns);
}

TEST(LockinAggregation, StatisticallyIdenticalToPerClock) {
  const TofLockinConfig cfg = test::edited_config({{"pixel", "rows", "1"}});
  const Samples agg = run(cfg, true, 3e-10, 21), clk = run(cfg, false, 3e-10, 22);
  ASSERT_EQ(agg.tap[0].size(), 30u * 64u);
  ASSERT_EQ(agg.range.size(), clk.range.size());
  for (int t = 0; t < 2; ++t) {
    const TwoSampleComparison c = compare_samples(agg.tap[t], clk.tap[t]);
    EXPECT_TRUE(c.indistinguishable()) << "tap " << t + 1 << ": " << describe(c);
    EXPECT_GT(c.var_a, 0.0);  // noise really on
  }
  const TwoSampleComparison r = compare_samples(agg.range, clk.range);
  EXPECT_TRUE(r.indistinguishable()) << "range: " << describe(r);
}

TEST(LockinAggregation, TestRejectsThreePercentMoreSignal) {
  const TofLockinConfig cfg = test::edited_config({{"pixel", "rows", "1"}});
  const Samples agg = run(cfg, true, 3e-10, 21), off = run(cfg, true, 3.09e-10, 23);
  const TwoSampleComparison c = compare_samples(agg.tap[0], off.tap[0]);
  EXPECT_FALSE(c.indistinguishable()) << describe(c);
}

}  // namespace
}  // namespace rangesim::systemc::lockin
