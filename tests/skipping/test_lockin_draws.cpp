// The samplers of tof-lockin's merged frame draws (systemc/tof_lockin/frame_draw.h) against their
// exact laws: the counter-based stream (words a pure function of key and counter, uniform), the
// ziggurat normal (moments, one-sample KS against the normal CDF, the tail beyond r) and the
// Poisson alias tables (every count's probability read back from the table against the pmf, the
// mass left out, and draws against the pmf). Sampling tests use the aggregation proofs' rule
// (means and variances within 5 standard errors, KS p >= 0.001); each has a companion showing the
// rule rejects a 3 % change.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "app/bench/bench_stats.h"
#include "systemc/common/poisson_sampler.h"
#include "systemc/tof_lockin/counter_stream.h"
#include "systemc/tof_lockin/normal_ziggurat.h"
#include "systemc/tof_lockin/alias_table.h"

namespace rangesim::systemc::lockin {
namespace {

using app::bench::compare_samples;
using app::bench::kolmogorov_q;
using app::bench::moments;

// One-sample KS p-value of x against the CDF F.
template <class Cdf>
double ks_p(std::vector<double> x, Cdf F) {
  std::sort(x.begin(), x.end());
  const double n = static_cast<double>(x.size());
  double d = 0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double f = F(x[i]);
    d = std::max({d, std::fabs(f - static_cast<double>(i) / n), std::fabs(static_cast<double>(i + 1) / n - f)});
  }
  return kolmogorov_q((std::sqrt(n) + 0.12 + 0.11 / std::sqrt(n)) * d);
}

double normal_cdf(double x) { return 0.5 * std::erfc(-x / std::sqrt(2.0)); }

// Mean 0 and variance 1 within 5 SE and KS p >= 0.001 against sigma x N(0, 1).
bool normal_with_sigma(const std::vector<double>& x, double sigma) {
  const auto m = moments(x);
  const double n = m.n;
  const double mean_z = m.mean / (sigma / std::sqrt(n));
  const double var_z = (m.var - sigma * sigma) / std::sqrt((m.m4 - m.var * m.var) / n);
  const double p = ks_p(x, [&](double v) { return normal_cdf(v / sigma); });
  return std::fabs(mean_z) < 5 && std::fabs(var_z) < 5 && p >= 1e-3;
}

std::vector<double> ziggurat_draws(std::size_t n, std::uint64_t key, double scale = 1.0) {
  CounterStream s(key);
  const NormalZiggurat& z = NormalZiggurat::tables();
  std::vector<double> x(n);
  for (double& v : x) v = scale * z(s);
  return x;
}

TEST(CounterStream, WordsArePureFunctionsOfKeyAndCounter) {
  CounterStream a(42), b(42), c(43);
  for (std::uint64_t i = 0; i < 1000; ++i) {
    const std::uint64_t w = a.next();
    EXPECT_EQ(w, b.word(i));
    EXPECT_NE(w, c.word(i));
  }
  EXPECT_EQ(a.counter(), 1000u);
}

TEST(CounterStream, UniformAndUncorrelatedAcrossKeysAndCounters) {
  // 2^20 uniforms from 2^10 consecutive keys x 2^10 words: KS against U(0, 1), and the
  // correlation of each word with the next key's same word and with its own next word.
  std::vector<double> u;
  double cross = 0, serial = 0;
  const int keys = 1024, words = 1024;
  for (int k = 0; k < keys; ++k) {
    CounterStream s(static_cast<std::uint64_t>(k)), t(static_cast<std::uint64_t>(k + 1));
    for (int i = 0; i < words; ++i) {
      const double x = open01(s.word(static_cast<std::uint64_t>(i))) - 0.5;
      u.push_back(x + 0.5);
      cross += x * (open01(t.word(static_cast<std::uint64_t>(i))) - 0.5);
      serial += x * (open01(s.word(static_cast<std::uint64_t>(i + 1))) - 0.5);
    }
  }
  const double n = static_cast<double>(u.size()), se = (1.0 / 12) / std::sqrt(n);
  EXPECT_GE(ks_p(u, [](double v) { return v; }), 1e-3);
  EXPECT_LT(std::fabs(cross / n) / se, 5);
  EXPECT_LT(std::fabs(serial / n) / se, 5);
}

TEST(NormalZiggurat, RegionsCloseAtTheTop) {
  const NormalZiggurat& z = NormalZiggurat::tables();
  // The 256-region edge of Marsaglia and Tsang (r = 3.6541528853610088, v = 0.00492867323399).
  EXPECT_NEAR(z.r(), 3.6541528853610088, 1e-12);
  EXPECT_NEAR(z.area(), 0.00492867323399, 1e-13);
}

TEST(NormalZiggurat, IsTheStandardNormalLaw) {
  const std::vector<double> x = ziggurat_draws(1 << 20, 7);
  EXPECT_TRUE(normal_with_sigma(x, 1.0));
  // The tail region's draws: P(|x| > r) = 2 (1 - Phi(r)) = 2.58e-4, binomial within 5 SE.
  const double r = NormalZiggurat::tables().r(), p = 2 * (1 - normal_cdf(r)), n = static_cast<double>(x.size());
  const double beyond =
      static_cast<double>(std::count_if(x.begin(), x.end(), [&](double v) { return std::fabs(v) > r; }));
  EXPECT_LT(std::fabs(beyond - n * p) / std::sqrt(n * p * (1 - p)), 5) << beyond;
  // And beyond 4.5 (deep in the tail): expected 7.1.
  const double far =
      static_cast<double>(std::count_if(x.begin(), x.end(), [](double v) { return std::fabs(v) > 4.5; }));
  EXPECT_LT(far, 7.1 + 5 * std::sqrt(7.1));
  EXPECT_GT(far, 0);
}

TEST(NormalZiggurat, TestRejectsThreePercentWider) {
  EXPECT_FALSE(normal_with_sigma(ziggurat_draws(1 << 20, 8, 1.03), 1.0));
}

// The Poisson pmf in long double, independently of the table: lgammal for small k; for k >= 16
// Stirling's series for ln k! written so that the terms of size mu ln mu cancel analytically
// (k ln(1 + d/k) - d - ln(2 pi k)/2 - 1/(12k) + 1/(360k^3) - ..., d = mu - k): the direct sum
// loses ~1e-11 relative at mu = 1e6 even in long double.
long double pmf(double mu, long long k) {
  if (mu == 0) return k == 0 ? 1 : 0;
  const long double m = mu, kk = static_cast<long double>(k);
  if (k < 16) return std::exp(-m + kk * std::log(m) - std::lgamma(kk + 1));
  const long double d = m - kk, ik = 1 / kk, ik2 = ik * ik;
  const long double r = ik * (1.0L / 12 - ik2 * (1.0L / 360 - ik2 * (1.0L / 1260 - ik2 / 1680)));
  return std::exp(kk * std::log1p(d / kk) - d - 0.5L * std::log(2 * std::acos(-1.0L) * kk) - r);
}

TEST(PoissonAlias, TableProbabilitiesAreThePmf) {
  for (double mu : {0.0, 0.3, 7.0, 250.0, 1248.0, 17000.5, 1e6}) {
    const PoissonAlias t(mu);
    long double worst = 0, inside = 0;
    const std::vector<long double> table = t.probabilities();
    for (long long k = t.first(); k <= t.last(); ++k) {
      const long double p = pmf(mu, k), q = table[static_cast<std::size_t>(k - t.first())];
      inside += p;
      worst = std::max(worst, std::fabs(q - p));
    }
    // Relative to the largest probability: the pmf's own rounding in lgammal at k ~ 1e6 is ~1e-13.
    EXPECT_LT(static_cast<double>(worst), 2e-12 * static_cast<double>(pmf(mu, static_cast<long long>(mu))))
        << "mu " << mu;
    // What the table leaves out is below its bound, and the bound below 2^-65.
    EXPECT_LE(static_cast<double>(1 - inside), t.mass_left_out() + 1e-15) << "mu " << mu;
    EXPECT_LT(t.mass_left_out(), std::ldexp(1.0, -65)) << "mu " << mu;
  }
}

std::vector<double> alias_draws(double mu, std::uint64_t key, int n = 200000) {
  const PoissonAlias t(mu);
  CounterStream s(key);
  std::vector<double> x(static_cast<std::size_t>(n));
  for (double& v : x) v = static_cast<double>(t(s));
  return x;
}

std::vector<double> ptrs_draws(double mu, std::uint64_t key, int n = 200000) {
  const PoissonSampler p(mu);
  CounterStream s(key);
  std::vector<double> x(static_cast<std::size_t>(n));
  for (double& v : x) v = static_cast<double>(p(s));
  return x;
}

TEST(PoissonAlias, DrawsArePoissonAndAgreeWithPtrs) {
  std::uint64_t key = 100;
  for (double mu : {0.3, 7.0, 1248.0, 17000.5}) {
    const std::vector<double> a = alias_draws(mu, key++);
    const auto m = moments(a);
    EXPECT_LT(std::fabs(m.mean - mu) / std::sqrt(mu / m.n), 5) << "mu " << mu;
    EXPECT_LT(std::fabs(m.var - mu) / std::sqrt((m.m4 - m.var * m.var) / m.n), 5) << "mu " << mu;
    // Against the PTRS sampler of systemc/common on the same stream type (its own proofs: PoissonSampler.*).
    const auto c = compare_samples(a, ptrs_draws(mu, key++));
    EXPECT_TRUE(c.indistinguishable()) << "mu " << mu << ": " << c.mean_z << " " << c.var_z << " " << c.ks_p;
  }
}

TEST(PoissonAlias, TestRejectsThreePercentMoreMean) {
  for (double mu : {1248.0, 17000.5}) {
    const auto c = compare_samples(alias_draws(1.03 * mu, 7), ptrs_draws(mu, 8));
    EXPECT_FALSE(c.indistinguishable()) << "mu " << mu;
  }
}

}  // namespace
}  // namespace rangesim::systemc::lockin
