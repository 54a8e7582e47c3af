// tof-spad sparse pixels (TofSpadKernelOptions::sparse, `rangesim simulate --dense` / `--no-sparse`
// turns it off): TDC groups whose pixels receive no echo (signal 0, same background) are one class,
// drawn in closed form (one multinomial over the L laser cycles, systemc/tof_spad/spad_aggregation.h)
// where pure-background cycles are independent, else run per cycle as before. Against the same
// groups run per cycle (the dense path, aggregation off both ways):
//   - deterministic parts identical: frame and phase cycles, STARTs; groups with an echo and
//     background-only groups of a configuration where the closed form is not exact (the preset)
//     bit-identical; with no arrivals at all (noise-free) the class's histogram equals the
//     per-cycle one bit for bit in any configuration;
//   - stated test, fixed seeds, 300 groups x 4 pixels each way: per code the per-pixel event
//     counts' mean and variance within 5 standard errors, the same for armed counts, overflows,
//     avalanches and photons per group; per-pixel total counts, peak code and range estimate:
//     mean and variance within 5 SE and two-sample KS p >= 0.001 (app/bench/bench_stats.h); the
//     detection fraction within 5 SE (two proportions). The same test rejects 3% more background.
#include <gtest/gtest.h>

#include <cmath>

#include "../systemc/tof_spad/spad_clock_helpers.h"
#include "app/bench/bench_stats.h"
#include "systemc/tof_spad/spad_aggregation.h"

namespace rangesim::systemc::spad {
namespace {

using app::bench::compare_samples;
using app::bench::TwoSampleComparison;

constexpr int kGroups = 300;

// Pure-background cycles independent: no afterpulse, dead time 0, no jitter, TDC re-armed by the
// next START (20 ns range, 4 ns busy); 1 ms = 40,000 laser cycles.
TofSpadConfig exact_config() {
  TofSpadConfig cfg = tof_spad_from_params(test::preset());
  cfg.spad.dead_time_s = 0;
  cfg.spad.afterpulse_probability = 0;
  cfg.spad.jitter_sigma_s = 0;
  cfg.tdc.full_range_s = 20e-9;
  cfg.tdc.busy_time_s = 4e-9;
  cfg.histogram.integration_time_s = 1e-3;
  return cfg;
}

TofSpadKernel kernel(const TofSpadConfig& cfg, bool sparse, std::uint64_t seed, int groups = kGroups,
                     SpadNoise noise = {}) {
  TofSpadKernelOptions o;
  o.seed = seed;
  o.sparse = sparse;
  o.noise = noise;
  return TofSpadKernel(cfg, 1, groups * cfg.tdc.columns_per_tdc, o);
}

PixelSelection all_groups(int groups) {
  PixelSelection sel;
  sel.rows = {0};
  sel.groups = groups;
  return sel;
}

struct Samples {
  std::vector<std::vector<double>> bin, armed;  // [code][pixel], [code][group]
  std::vector<double> total, peak, range, detected, overflows, avalanches, photons;
  long long background_groups = 0;
};

Samples run(const TofSpadConfig& cfg, bool sparse, double background_Hz, std::uint64_t seed) {
  const TofSpadKernel k = kernel(cfg, sparse, seed);
  const RateSource rates = test::flat(0, background_Hz, 2 * 2.0 / 299792458.0);
  Samples s;
  s.bin.assign(static_cast<size_t>(k.codes()), {});
  s.armed.assign(static_cast<size_t>(k.codes()), {});
  const FrameResult f = k.run_frame(0, all_groups(kGroups), rates);
  s.background_groups = f.groups_background;
  for (int g = 0; g < kGroups; ++g) {
    const GroupHistogram h = k.simulate_group(0, 0, g, rates);  // the same draws as the frame's
    s.overflows.push_back(static_cast<double>(h.overflows));
    s.avalanches.push_back(static_cast<double>(h.avalanches));
    s.photons.push_back(static_cast<double>(h.photons));
    for (int i = 0; i < k.codes(); ++i)
      s.armed[static_cast<size_t>(i)].push_back(static_cast<double>(h.armed[static_cast<size_t>(i)]));
  }
  for (const PixelResult& p : f.pixels) {
    double total = 0;
    for (int i = 0; i < k.codes(); ++i) {
      s.bin[static_cast<size_t>(i)].push_back(static_cast<double>(p.events[static_cast<size_t>(i)]));
      total += static_cast<double>(p.events[static_cast<size_t>(i)]);
    }
    s.total.push_back(total);
    s.peak.push_back(static_cast<double>(std::max_element(p.events.begin(), p.events.end()) - p.events.begin()));
    s.detected.push_back(p.time_s ? 1.0 : 0.0);
    s.range.push_back(p.time_s ? p.range_m : -1.0);
  }
  return s;
}

bool moments_agree(const std::vector<double>& a, const std::vector<double>& b) {
  const TwoSampleComparison c = compare_samples(a, b);
  return std::fabs(c.mean_z) < 5 && std::fabs(c.var_z) < 5;
}

// The stated test; returns the failures (empty: statistically identical).
std::vector<std::string> differences(const Samples& a, const Samples& b) {
  std::vector<std::string> bad;
  for (size_t i = 0; i < a.bin.size(); ++i) {
    if (!moments_agree(a.bin[i], b.bin[i])) bad.push_back("events of code " + std::to_string(i));
    if (!moments_agree(a.armed[i], b.armed[i])) bad.push_back("armed of code " + std::to_string(i));
  }
  if (!moments_agree(a.overflows, b.overflows)) bad.push_back("overflows");
  if (!moments_agree(a.avalanches, b.avalanches)) bad.push_back("avalanches");
  if (!moments_agree(a.photons, b.photons)) bad.push_back("photons");
  for (const auto& [name, x, y] :
       {std::tuple{"total counts", &a.total, &b.total}, std::tuple{"peak code", &a.peak, &b.peak},
        std::tuple{"range", &a.range, &b.range}}) {
    const TwoSampleComparison c = compare_samples(*x, *y);
    if (!c.indistinguishable())
      bad.push_back(std::string(name) + ": mean " + std::to_string(c.mean_z) + " SE, var " + std::to_string(c.var_z) +
                    " SE, KS p " + std::to_string(c.ks_p));
  }
  // Detection fraction: two proportions, pooled standard error.
  const double n = static_cast<double>(a.detected.size()), m = static_cast<double>(b.detected.size());
  double pa = 0, pb = 0;
  for (double v : a.detected) pa += v / n;
  for (double v : b.detected) pb += v / m;
  const double pool = (pa * n + pb * m) / (n + m), se = std::sqrt(pool * (1 - pool) * (1 / n + 1 / m));
  if (se > 0 ? std::fabs(pa - pb) > 5 * se : pa != pb)
    bad.push_back("detection fraction " + std::to_string(pa) + " vs " + std::to_string(pb));
  return bad;
}

TEST(SpadBackground, ClassPathAndDeterministicPartsIdentical) {
  const TofSpadConfig exact = exact_config();
  EXPECT_EQ(kernel(exact, true, 1, 2).background_blocker(), "");
  // The preset's dead time, afterpulses, jitter and busy time couple successive cycles.
  TofSpadConfig preset = tof_spad_from_params(test::preset());
  preset.histogram.integration_time_s = 2e-4;
  EXPECT_NE(kernel(preset, true, 1, 2).background_blocker(), "");
  // Group 0 has an echo on one pixel, group 1 is background only.
  const RateSource spot = [](int, int col) { return PixelRates{col == 2 ? 2e5 : 0.0, 1e6, 2e-8}; };
  for (const TofSpadConfig* cfg : std::vector<const TofSpadConfig*>{&exact, &preset}) {
    const TofSpadKernel ks = kernel(*cfg, true, 7, 2), kd = kernel(*cfg, false, 7, 2);
    const FrameResult fs = ks.run_frame(0, all_groups(2), spot), fd = kd.run_frame(0, all_groups(2), spot);
    EXPECT_EQ(fs.cycles, fd.cycles);
    EXPECT_EQ(fs.phase_cycles, fd.phase_cycles);
    EXPECT_EQ(fd.groups_background, 0);
    const GroupHistogram echo_s = ks.simulate_group(0, 0, 0, spot), echo_d = kd.simulate_group(0, 0, 0, spot);
    EXPECT_FALSE(echo_s.background_class);
    test::expect_same_histogram(echo_s, echo_d);
    const GroupHistogram bg_s = ks.simulate_group(0, 0, 1, spot), bg_d = kd.simulate_group(0, 0, 1, spot);
    EXPECT_EQ(bg_s.starts, bg_d.starts);
    if (cfg == &exact) {
      EXPECT_TRUE(bg_s.background_class);
      EXPECT_EQ(fs.groups_background, 1);
      EXPECT_GT(bg_s.avalanches, 0);
    } else {
      // Not exact there: the background-only group runs per cycle, bit-identical, and is counted.
      EXPECT_FALSE(bg_s.background_class);
      EXPECT_EQ(fs.groups_background, 0);
      EXPECT_EQ(fs.groups_background_per_cycle, 1);
      test::expect_same_histogram(bg_s, bg_d);
    }
    // No arrivals at all (noise-free, no echo): the class's empty histogram in any configuration,
    // equal to the per-cycle one bit for bit.
    const TofSpadKernel ns = kernel(*cfg, true, 7, 2, SpadNoise::none()),
                        nd = kernel(*cfg, false, 7, 2, SpadNoise::none());
    const GroupHistogram e_s = ns.simulate_group(0, 0, 1, spot), e_d = nd.simulate_group(0, 0, 1, spot);
    EXPECT_TRUE(e_s.background_class);
    test::expect_same_histogram(e_s, e_d);
    EXPECT_EQ(e_s.armed.front(), ns.laser_cycles());
  }
}

TEST(SpadBackground, StatisticallyIdenticalToPerCycle) {
  const TofSpadConfig cfg = exact_config();
  const std::uint64_t seed = test::test_seed();
  const Samples cls = run(cfg, true, 2e6, 100 + seed), cyc = run(cfg, false, 2e6, 200 + seed);
  ASSERT_EQ(cls.background_groups, kGroups);
  ASSERT_EQ(cyc.background_groups, 0);
  // Pile-up matters: the group detects in about one cycle in six (1 - exp(-4 pixels x 2 MHz x
  // 25 ns) = 18%, the TDC range covering 20 of the 25 ns).
  double events = 0;
  for (double v : cls.total) events += v;
  EXPECT_GT(events / kGroups, 0.1 * 40000);
  const std::vector<std::string> bad = differences(cls, cyc);
  EXPECT_TRUE(bad.empty()) << ::testing::PrintToString(bad);
}

TEST(SpadBackground, TestRejectsThreePercentMoreBackground) {
  const TofSpadConfig cfg = exact_config();
  const std::uint64_t seed = test::test_seed();
  const Samples cls = run(cfg, true, 2e6, 100 + seed), more = run(cfg, true, 2.06e6, 300 + seed);
  EXPECT_FALSE(differences(cls, more).empty());
}

}  // namespace
}  // namespace rangesim::systemc::spad
