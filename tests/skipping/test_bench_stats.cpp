// The two-sample statistics behind "statistically indistinguishable" (app/bench/bench_stats.h):
// the Kolmogorov distribution at known points, same-distribution samples pass, a small shift in
// mean or in spread is caught.
#include <gtest/gtest.h>

#include <random>

#include "app/bench/bench_stats.h"

namespace rangesim::app::bench {
namespace {

std::vector<double> normal(int n, double mean, double sd, std::uint64_t seed) {
  std::mt19937_64 g(seed);
  std::normal_distribution<double> d(mean, sd);
  std::vector<double> v(static_cast<std::size_t>(n));
  for (auto& x : v) x = d(g);
  return v;
}

TEST(BenchStats, KolmogorovTailAtKnownPoints) {
  EXPECT_NEAR(kolmogorov_q(1.36), 0.049, 0.002);   // the 5% critical value
  EXPECT_NEAR(kolmogorov_q(1.628), 0.010, 0.001);  // 1%
  EXPECT_DOUBLE_EQ(kolmogorov_q(0.1), 1.0);
}

TEST(BenchStats, SameDistributionPassesShiftsFail) {
  const auto a = normal(4000, 10, 2, 1), b = normal(4000, 10, 2, 2);
  EXPECT_TRUE(compare_samples(a, b).indistinguishable());
  const auto shifted = normal(4000, 10.5, 2, 3);  // 0.25 sigma: expected 11 SE
  const TwoSampleComparison s = compare_samples(a, shifted);
  EXPECT_FALSE(s.indistinguishable());
  EXPECT_LT(s.mean_z, -5);
  const auto wider = normal(4000, 10, 2.3, 4);  // 15% wider
  const TwoSampleComparison w = compare_samples(a, wider);
  EXPECT_FALSE(w.indistinguishable());
  EXPECT_LT(w.var_z, -5);
}

}  // namespace
}  // namespace rangesim::app::bench
