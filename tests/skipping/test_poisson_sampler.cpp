// The pixel kernels' own samplers (systemc/common/poisson_sampler.h) against independent references:
// PoissonSampler against std::poisson_distribution and the exact mean and variance mu, on both of
// its paths (inversion below mu = 10, PTRS above) and at the boundary; standard_normal_pair
// against std::normal_distribution, its two values uncorrelated. Same decision rule as the
// aggregation proofs (app/bench/bench_stats.h: means and variances within 5 standard errors,
// two-sample KS p >= 0.001), and a companion test that the rule rejects a 3 % change of mu.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "app/bench/bench_stats.h"
#include "systemc/common/poisson_sampler.h"

namespace {

using rangesim::app::bench::compare_samples;
using rangesim::app::bench::moments;
namespace sc = rangesim::systemc;

constexpr int kDraws = 20000;

std::vector<double> sampler_draws(double mu, std::uint64_t seed) {
  const sc::PoissonSampler s(mu);
  pcg32 rng = sc::pixel_stream(sc::pixel_stream_key(seed, 0, 0, 0));
  std::vector<double> x(kDraws);
  for (double& v : x) v = static_cast<double>(s(rng));
  return x;
}

std::vector<double> reference_draws(double mu, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::poisson_distribution<long long> p(mu);
  std::vector<double> x(kDraws);
  for (double& v : x) v = static_cast<double>(p(rng));
  return x;
}

TEST(PoissonSampler, StatisticallyIdenticalToStdPoissonOnBothPaths) {
  std::uint64_t seed = 11;
  for (double mu : {0.3, 2.0, 9.99, 10.0, 37.0, 480.0, 2.6e4}) {
    const std::vector<double> a = sampler_draws(mu, seed++), b = reference_draws(mu, seed++);
    const auto c = compare_samples(a, b);
    EXPECT_TRUE(c.indistinguishable()) << "mu " << mu << ": mean z " << c.mean_z << " var z " << c.var_z << " KS p "
                                       << c.ks_p;
    // And against the exact moments: E = Var = mu.
    const auto m = moments(a);
    EXPECT_LT(std::abs(m.mean - mu) / std::sqrt(mu / kDraws), 5) << "mu " << mu << " mean " << m.mean;
    const double se_var = std::sqrt((m.m4 - m.var * m.var) / kDraws);
    EXPECT_LT(std::abs(m.var - mu) / se_var, 5) << "mu " << mu << " var " << m.var;
  }
}

TEST(PoissonSampler, TestRejectsThreePercentMoreMean) {
  std::uint64_t seed = 101;
  for (double mu : {37.0, 2.6e4}) {
    const auto c = compare_samples(sampler_draws(1.03 * mu, seed), reference_draws(mu, seed + 1));
    seed += 2;
    EXPECT_FALSE(c.indistinguishable()) << "mu " << mu << ": mean z " << c.mean_z << " KS p " << c.ks_p;
  }
}

TEST(PoissonSampler, ZeroMeanDrawsZero) {
  pcg32 rng = sc::pixel_stream(1);
  const sc::PoissonSampler s(0.0);
  for (int i = 0; i < 100; ++i) EXPECT_EQ(s(rng), 0);
}

// The rare exact acceptance test of PTRS compares against log p(k). Summed directly,
// -mu + k ln mu - ln k! loses ~1e-2 at mu = 1e12 (aggregated lock-in charges reach 1e15 e-).
// The pmf it gives must still sum to 1 and keep the ratio of neighbours p(k+1)/p(k) = mu/(k+1).
TEST(PoissonSampler, LogPmfKeepsItsDigitsAtHugeMeans) {
  for (double mu : {1e6, 1e9, 1e12, 1e14}) {
    const double sd = std::sqrt(mu);
    double worst_ratio = 0, worst_direct = 0;
    for (double z = -6; z <= 6; z += 0.25) {
      const double k = std::floor(mu + z * sd);
      const double step = sc::PoissonSampler::log_pmf(mu, k + 1) - sc::PoissonSampler::log_pmf(mu, k);
      worst_ratio = std::max(worst_ratio, std::abs(step - std::log(mu / (k + 1))));
      const long double direct = -static_cast<long double>(mu) + k * std::log(static_cast<long double>(mu)) -
                                 std::lgamma(static_cast<long double>(k) + 1);
      worst_direct = std::max(worst_direct, static_cast<double>(std::abs(direct - sc::PoissonSampler::log_pmf(mu, k))));
    }
    // What is left is the rounding of terms of size d = 6 sd: d x 1e-16 (the direct sum: mu ln mu x 1e-16).
    EXPECT_LT(worst_ratio, 1e-9 + 6 * sd * 1e-15) << "mu " << mu;
    // long double keeps 64 bits: its own error is about mu ln mu x 1e-19.
    EXPECT_LT(worst_direct, 1e-8 + mu * std::log(mu) * 4e-19) << "mu " << mu;
  }
  // Normalisation over +-9 sd at mu = 1e12 (the direct double sum is off by ~1e-2 here).
  const double mu = 1e12, sd = 1e6;
  long double sum = 0;
  for (double k = std::floor(mu - 9 * sd); k <= mu + 9 * sd; k += 1)
    sum += std::exp(sc::PoissonSampler::log_pmf(mu, k));
  EXPECT_NEAR(static_cast<double>(sum), 1.0, 1e-8);
  // Small k keep the direct form; the two forms meet at k = 16.
  for (double m : {10.0, 16.0, 40.0})
    for (double k = 0; k <= 60; k += 1)
      EXPECT_NEAR(sc::PoissonSampler::log_pmf(m, k), -m + k * std::log(m) - std::lgamma(k + 1), 1e-11) << m << " " << k;
}

TEST(StandardNormalPair, StatisticallyIdenticalToStdNormalAndUncorrelated) {
  pcg32 rng = sc::pixel_stream(sc::pixel_stream_key(7, 1, 2, 3));
  std::vector<double> z1(kDraws), z2(kDraws), ref(kDraws);
  for (int i = 0; i < kDraws; ++i)
    sc::standard_normal_pair(rng, z1[static_cast<std::size_t>(i)], z2[static_cast<std::size_t>(i)]);
  std::mt19937_64 mt(5);
  std::normal_distribution<double> n;
  for (double& v : ref) v = n(mt);
  for (const auto* z : {&z1, &z2}) {
    const auto c = compare_samples(*z, ref);
    EXPECT_TRUE(c.indistinguishable()) << "mean z " << c.mean_z << " var z " << c.var_z << " KS p " << c.ks_p;
  }
  double cov = 0;
  for (int i = 0; i < kDraws; ++i) cov += z1[static_cast<std::size_t>(i)] * z2[static_cast<std::size_t>(i)];
  EXPECT_LT(std::abs(cov / kDraws) * std::sqrt(kDraws), 5);  // correlation within 5 SE of 0
}

TEST(StandardNormalPair, TestRejectsThreePercentWiderNormal) {
  pcg32 rng = sc::pixel_stream(3);
  std::vector<double> z(4 * kDraws), ref(4 * kDraws);
  for (std::size_t i = 0; i < z.size(); i += 2) {
    sc::standard_normal_pair(rng, z[i], z[i + 1]);
    z[i] *= 1.03, z[i + 1] *= 1.03;
  }
  std::mt19937_64 mt(9);
  std::normal_distribution<double> n;
  for (double& v : ref) v = n(mt);
  EXPECT_FALSE(compare_samples(z, ref).indistinguishable());
}

}  // namespace
