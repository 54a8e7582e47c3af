// tof-spad aggregation (TofSpadKernelOptions::aggregate: the L laser cycles of a row integration
// as one multinomial draw over (column, code) + overflow + "no detection", systemc/tof_spad/
// spad_aggregation.h) against the same groups run cycle by cycle (event-driven per-cycle path,
// itself proved equal to the clock-by-clock TDC in SpadTick.*). Configuration where aggregation is
// exact: no afterpulses, dead time 0, no jitter, TDC re-armed by the next START (20 ns range, 4 ns
// busy). Stated test, at fixed seeds, on 300 groups x 4 pixels each way: for every code, the
// per-pixel event counts' means and variances within 5 standard errors; the same for the armed
// counts, overflows and avalanches per group; and on the range estimate and the peak code the
// means, variances within 5 SE and a two-sample Kolmogorov-Smirnov p >= 0.001
// (app/bench/bench_stats.h). The same test must reject a run with 3% more signal.
#include <gtest/gtest.h>

#include "../systemc/tof_spad/spad_clock_helpers.h"
#include "app/bench/bench_stats.h"
#include "systemc/tof_spad/spad_aggregation.h"

namespace rangesim::systemc::spad {
namespace {

using app::bench::compare_samples;
using app::bench::TwoSampleComparison;

constexpr int kGroups = 300;

TofSpadConfig exact_config() {
  TofSpadConfig cfg = tof_spad_from_params(test::preset());
  cfg.spad.dead_time_s = 0;
  cfg.spad.afterpulse_probability = 0;
  cfg.spad.jitter_sigma_s = 0;
  cfg.tdc.full_range_s = 20e-9;
  cfg.tdc.busy_time_s = 4e-9;
  cfg.histogram.integration_time_s = 1e-3;  // 40,000 laser cycles
  return cfg;
}

struct SpadRun {
  std::vector<std::vector<double>> bin;    // [code][pixel sample]
  std::vector<std::vector<double>> armed;  // [code][group sample]
  std::vector<double> overflows, avalanches, range, peak;
  long long aggregated_groups = 0;
};

SpadRun run(const TofSpadConfig& cfg, bool aggregate, double signal_Hz, std::uint64_t seed) {
  TofSpadKernelOptions o;
  o.seed = seed;
  o.aggregate = aggregate;
  const TofSpadKernel k(cfg, 1, kGroups * cfg.tdc.columns_per_tdc, o);
  const RateSource rates = test::flat(signal_Hz, 1e6, 2 * 2.0 / 299792458.0);
  SpadRun r;
  r.bin.assign(static_cast<size_t>(k.codes()), {});
  r.armed.assign(static_cast<size_t>(k.codes()), {});
  for (int g = 0; g < kGroups; ++g) {
    const GroupHistogram h = k.simulate_group(0, 0, g, rates);
    r.aggregated_groups += h.aggregated;
    r.overflows.push_back(static_cast<double>(h.overflows));
    r.avalanches.push_back(static_cast<double>(h.avalanches));
    for (int i = 0; i < k.codes(); ++i)
      r.armed[static_cast<size_t>(i)].push_back(static_cast<double>(h.armed[static_cast<size_t>(i)]));
    for (int p = 0; p < cfg.tdc.columns_per_tdc; ++p) {
      const auto& ev = h.events[static_cast<size_t>(p)];
      for (int i = 0; i < k.codes(); ++i)
        r.bin[static_cast<size_t>(i)].push_back(static_cast<double>(ev[static_cast<size_t>(i)]));
      r.peak.push_back(static_cast<double>(std::max_element(ev.begin(), ev.end()) - ev.begin()));
      const PixelResult px = k.make_pixel(0, g * cfg.tdc.columns_per_tdc + p, h, p);
      r.range.push_back(px.time_s ? px.range_m : -1.0);
    }
  }
  return r;
}

bool moments_agree(const std::vector<double>& a, const std::vector<double>& b) {
  const TwoSampleComparison c = compare_samples(a, b);
  return std::fabs(c.mean_z) < 5 && std::fabs(c.var_z) < 5;
}

// The stated test; returns the failures (empty: statistically identical).
std::vector<std::string> differences(const SpadRun& a, const SpadRun& b) {
  std::vector<std::string> bad;
  for (size_t i = 0; i < a.bin.size(); ++i) {
    if (!moments_agree(a.bin[i], b.bin[i])) bad.push_back("events of code " + std::to_string(i));
    if (!moments_agree(a.armed[i], b.armed[i])) bad.push_back("armed of code " + std::to_string(i));
  }
  if (!moments_agree(a.overflows, b.overflows)) bad.push_back("overflows");
  if (!moments_agree(a.avalanches, b.avalanches)) bad.push_back("avalanches");
  for (const auto& [name, x, y] :
       {std::tuple{"range", &a.range, &b.range}, std::tuple{"peak code", &a.peak, &b.peak}}) {
    const TwoSampleComparison c = compare_samples(*x, *y);
    if (!c.indistinguishable())
      bad.push_back(std::string(name) + ": mean " + std::to_string(c.mean_z) + " SE, var " + std::to_string(c.var_z) +
                    " SE, KS p " + std::to_string(c.ks_p));
  }
  return bad;
}

TEST(SpadAggregation, ExactConfigurationIsAggregatedPresetIsNot) {
  const TofSpadConfig exact = exact_config();
  TofSpadKernelOptions o;
  o.aggregate = true;
  EXPECT_EQ(TofSpadKernel(exact, 1, 8, o).aggregation_blocker(), "");
  // The preset: afterpulses, 50 ns dead time, jitter, 100 ns busy time each couple successive cycles.
  const TofSpadConfig preset = tof_spad_from_params(test::preset());
  EXPECT_NE(TofSpadKernel(preset, 1, 8, o).aggregation_blocker(), "");
  TofSpadConfig c = exact;
  c.tdc.busy_time_s = 10e-9;  // event at code 203 + 102 bins > 256: carries into the next cycle
  EXPECT_NE(TofSpadKernel(c, 1, 8, o).aggregation_blocker().find("TDC blocked"), std::string::npos);
  c = exact, c.spad.dead_time_s = 1e-9;
  EXPECT_NE(TofSpadKernel(c, 1, 8, o).aggregation_blocker().find("dead time"), std::string::npos);
  // A group with different pixels falls back to the per-cycle path, an identical one does not.
  const TofSpadKernel k(exact, 1, 8, o);
  const RateSource step = [](int, int col) { return PixelRates{col == 5 ? 2e5 : 1e5, 1e5, 2e-8}; };
  EXPECT_TRUE(k.simulate_group(0, 0, 0, step).aggregated);
  EXPECT_FALSE(k.simulate_group(0, 0, 1, step).aggregated);
  // Keyed streams: the same group draws the same histogram again.
  EXPECT_EQ(k.simulate_group(3, 0, 0, step).events, k.simulate_group(3, 0, 0, step).events);
  // The preset's groups run per cycle even with aggregation requested.
  TofSpadConfig short_preset = preset;
  short_preset.histogram.integration_time_s = 1e-5;
  EXPECT_FALSE(TofSpadKernel(short_preset, 1, 8, o).simulate_group(0, 0, 0, test::flat(1e5, 1e5, 2e-8)).aggregated);
}

TEST(SpadAggregation, StatisticallyIdenticalToPerCycle) {
  const TofSpadConfig cfg = exact_config();
  const std::uint64_t s = test::test_seed();
  const SpadRun agg = run(cfg, true, 2e6, 100 + s), cyc = run(cfg, false, 2e6, 200 + s);
  ASSERT_EQ(agg.aggregated_groups, kGroups);
  ASSERT_EQ(cyc.aggregated_groups, 0);
  // The point is pile-up heavy: the group detects in ~30% of the cycles, so Coates matters.
  double events = 0;
  for (const auto& b : agg.bin)
    for (double v : b) events += v;
  EXPECT_GT(events / kGroups, 0.2 * 40000);
  const std::vector<std::string> bad = differences(agg, cyc);
  EXPECT_TRUE(bad.empty()) << ::testing::PrintToString(bad);
}

TEST(SpadAggregation, TestRejectsThreePercentMoreSignal) {
  const TofSpadConfig cfg = exact_config();
  const std::uint64_t s = test::test_seed();
  const SpadRun agg = run(cfg, true, 2e6, 100 + s), more = run(cfg, true, 2.06e6, 300 + s);
  EXPECT_FALSE(differences(agg, more).empty());
}

}  // namespace
}  // namespace rangesim::systemc::spad
