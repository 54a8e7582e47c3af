// Closed-form noise: activation probability against a brute-force sum, and the exact moments of
// the 1-bit multi-sampling estimate against a Monte Carlo of the same model. The Monte Carlo here
// is the bar any later Monte Carlo of the clock-level models must meet.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "golden/common/activation_cdf.h"
#include "golden/ls_conventional/detect.h"
#include "golden/ls_conventional/multisampling.h"
#include "golden/common/pixel.h"
#include "golden/common/position_noise.h"
#include "golden/common/row_model.h"
#include "golden/common/spot.h"
#include "test_helpers.h"

namespace rangesim::golden {
namespace {

// Direct sum over every n in a wide window, long double, pmf renormalised.
void reference_activation(double mu, double t, double s, long double& p, long double& q) {
  p = q = 0;
  const long nlo = static_cast<long>(std::max(0.0, std::floor(mu - 40 * std::sqrt(mu) - 60)));
  const long nhi = static_cast<long>(std::ceil(mu + 40 * std::sqrt(mu) + 60));
  const long double lm = std::log(static_cast<long double>(mu));
  long double tot = 0;
  for (long n = nlo; n <= nhi; ++n) {
    const long double pm = std::exp(n * lm - mu - std::lgamma(static_cast<long double>(n) + 1));
    long double up, down;
    if (s > 0) {
      const long double z = (n - t) / s;
      up = 0.5L * std::erfc(-z / std::sqrt(2.0L));
      down = 0.5L * std::erfc(z / std::sqrt(2.0L));
    } else {
      up = n >= t ? 1 : 0;
      down = 1 - up;
    }
    p += pm * up;
    q += pm * down;
    tot += pm;
  }
  p /= tot;
  q /= tot;
}

TEST(GoldenNoise, ActivationProbabilityHandValues) {
  // No static noise: Poisson upper tail. mu = 2, P(N >= 3) = 1 - e^-2 (1 + 2 + 2) = 0.3233235838.
  EXPECT_NEAR(activation_probability(2, 3, 0).p, 1 - std::exp(-2.0) * 5, 1e-15);
  EXPECT_NEAR(activation_probability(2, 2.5, 0).p, 1 - std::exp(-2.0) * 5, 1e-15);  // n >= ceil(t)
  // No electrons: the static noise alone, P(R >= t) = Phi(-t / s).
  EXPECT_NEAR(activation_probability(0, 100, 100).p, 0.5 * std::erfc(1 / std::sqrt(2.0)), 1e-15);
  // Far from the threshold: exactly 0 / 1 by the early exits.
  EXPECT_EQ(activation_probability(1000, 5000, 50).p, 0.0);
  EXPECT_EQ(activation_probability(5000, 1000, 50).q, 0.0);
}

TEST(GoldenNoise, ActivationProbabilityMatchesBruteForce) {
  std::mt19937_64 rng(11);
  double worst = 0;
  for (int i = 0; i < 300; ++i) {
    const double mu = std::exp(std::uniform_real_distribution<double>(std::log(0.2), std::log(4e5))(rng));
    const double s =
        i % 5 == 0 ? 0 : std::exp(std::uniform_real_distribution<double>(std::log(0.3), std::log(300))(rng));
    const double t = mu + std::normal_distribution<double>(0, 3)(rng) * std::sqrt(mu + s * s);
    long double p, q;
    reference_activation(mu, t, s, p, q);
    const ActivationProbability a = activation_probability(mu, t, s);
    // The long-double reference itself is good to ~1e-13 at mu ~ 4e5 (lgamma of 4e5).
    EXPECT_NEAR(a.p, static_cast<double>(p), 1e-12) << mu << " " << t << " " << s;
    EXPECT_NEAR(a.q, static_cast<double>(q), 1e-12) << mu << " " << t << " " << s;
    if (q < 1e-3 && q > 1e-14) {  // (below 1e-18 the early exit returns exactly 0)  // small tails stay accurate
      EXPECT_NEAR(a.q / static_cast<double>(q), 1, 1e-6);
    }
    worst = std::max(worst, std::fabs(a.p - static_cast<double>(p)));
  }
  RecordProperty("worst_abs_error", std::to_string(worst));
}

TEST(GoldenNoise, ExactMomentsTwoPixelHandCase) {
  // Two pixels at 0 and 1, one sampling: P(F_0 <= 1) = a, P(F_1 <= 1) = b.
  // Outcomes: {0}: centre 0, {1}: 1, {0,1}: 0.5. P(detect) = 1 - (1-a)(1-b).
  const double a = 0.3, b = 0.6;
  const std::vector<double> x{0, 1};
  const std::vector<std::vector<double>> C{{0, a, 1}, {0, b, 1}}, S{{1, 1 - a, 0}, {1, 1 - b, 0}};
  const PositionMoments m = edge_centre_moments(x, C, S, 1);
  const double p0 = a * (1 - b), p1 = (1 - a) * b, p01 = a * b, pd = p0 + p1 + p01;
  const double mean = (p1 * 1 + p01 * 0.5) / pd;
  const double var = (p1 * 1 + p01 * 0.25) / pd - mean * mean;
  EXPECT_NEAR(m.p_detect, pd, 1e-15);
  EXPECT_NEAR(m.mean_px, mean, 1e-15);
  EXPECT_NEAR(m.var_px2, var, 1e-15);
}

TEST(GoldenNoise, NoiselessLimitIsTheNoiseFreeEstimate) {
  LsConventionalConfig cfg = test::preset_config();
  cfg.pixel.read_noise_V = 0;
  cfg.pixel.temperature_K = 1e-9;      // no kTC
  cfg.pixel.pd_capacitance_F = 40e-9;  // 1e6 x the electrons per volt: shot noise 1000x smaller
  const RowModel row = make_row_model(cfg, 0.3, 0.01);
  for (double u : {-0.37, -0.1, 0.21, 0.44}) {
    const double x0 = row.centre_pixel + u;
    const PositionMoments m = position_moments(row, x0);
    const CentreEstimate nf = noise_free_estimate(row, x0);
    EXPECT_NEAR(m.p_detect, 1, 1e-12);
    EXPECT_NEAR(m.mean_px, nf.centre_px, 1e-9);
    EXPECT_NEAR(m.var_px2, 0, 1e-9);
  }
}

struct McResult {
  double p_detect, mean, var, se_p, se_mean, se_var;
};

// Monte Carlo of the same model: static offset R per pixel, Poisson increments between samplings,
// first activated sampling F_i, then the edge centres of the samplings from min F on.
McResult monte_carlo(const RowModel& row, double x0, int draws, std::uint64_t seed) {
  const int N = row.samplings, c = row.centre_pixel, lo = c - 20, hi = c + 20;
  const double thr = level_threshold_electrons(row, 1), sig = static_noise_electrons(row);
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> normal(0, 1);
  int detected = 0;
  double s1 = 0, s2 = 0, s3 = 0, s4 = 0;
  std::vector<int> F(hi - lo + 1);
  for (int d = 0; d < draws; ++d) {
    for (int i = lo; i <= hi; ++i) {
      const double R = sig * normal(rng);
      double n = 0, mu_prev = 0;
      int f = N + 1;
      for (int k = 1; k <= N; ++k) {
        const double mu = row_pixel_mean_electrons(row, i, x0, k);
        n += std::poisson_distribution<long>(mu - mu_prev)(rng);
        mu_prev = mu;
        if (n + R >= thr) {
          f = k;
          break;
        }
      }
      F[i - lo] = f;
    }
    int m = N + 1;
    for (int f : F) m = std::min(m, f);
    if (m > N) continue;
    double sum = 0;
    for (int k = m; k <= N; ++k) {
      int l = -1, r = -1;
      for (int j = 0; j < static_cast<int>(F.size()); ++j)
        if (F[j] <= k) {
          if (l < 0) l = j;
          r = j;
        }
      sum += 0.5 * (l + r) + lo;
    }
    const double xh = sum / (N - m + 1) - c;
    ++detected;
    s1 += xh;
    s2 += xh * xh;
    s3 += xh * xh * xh;
    s4 += xh * xh * xh * xh;
  }
  McResult r;
  r.p_detect = static_cast<double>(detected) / draws;
  r.se_p = std::sqrt(r.p_detect * (1 - r.p_detect) / draws) + 1e-12;
  const double n = detected;
  r.mean = s1 / n;
  r.var = s2 / n - r.mean * r.mean;
  r.se_mean = std::sqrt(r.var / n);
  // Central fourth moment for the standard error of the variance.
  const double m4 = s4 / n - 4 * r.mean * s3 / n + 6 * r.mean * r.mean * s2 / n - 3 * std::pow(r.mean, 4);
  r.se_var = std::sqrt(std::max(0.0, m4 - r.var * r.var) / n);
  r.mean += c;
  return r;
}

void expect_matches_monte_carlo(const RowModel& row, double x0, std::uint64_t seed) {
  const PositionMoments m = position_moments(row, x0);
  ASSERT_TRUE(m.exact);
  const McResult mc = monte_carlo(row, x0, 20000, seed);
  EXPECT_NEAR(m.p_detect, mc.p_detect, 5 * mc.se_p);
  EXPECT_NEAR(m.mean_px, mc.mean, 5 * mc.se_mean) << "var " << m.var_px2;
  EXPECT_NEAR(m.var_px2, mc.var, 5 * mc.se_var);
  ::testing::Test::RecordProperty("exact_var", std::to_string(m.var_px2));
  ::testing::Test::RecordProperty("mc_var", std::to_string(mc.var));
}

TEST(GoldenNoise, ExactMomentsMatchMonteCarloNearThreshold) {
  // Weak signal: detection is uncertain and the activated run flickers at its edges.
  const RowModel row = make_row_model(test::preset_config(), 0.0115, 0.001);
  expect_matches_monte_carlo(row, row.centre_pixel + 0.3, 1);
}

TEST(GoldenNoise, ExactMomentsMatchMonteCarloStrongBackground) {
  // Strong background: shot noise of 0.5 V of background electrons dominates.
  const RowModel row = make_row_model(test::preset_config(), 0.08, 0.5);
  expect_matches_monte_carlo(row, row.centre_pixel - 0.2, 2);
}

TEST(GoldenNoise, MultiBitIsFlaggedApproximate) {
  LsConventionalConfig cfg = test::preset_config();
  cfg.comparator.adc_bits = 3;
  const RowModel row = make_row_model(cfg, 0.3, 0.01);
  const PositionMoments m = position_moments(row, row.centre_pixel + 0.1);
  EXPECT_FALSE(m.exact);
  EXPECT_NEAR(m.p_detect, 1, 1e-12);
  EXPECT_NEAR(m.mean_px, row.centre_pixel + 0.1, 0.2);
  EXPECT_GT(m.var_px2, 0);
  EXPECT_LT(m.var_px2, 0.05);
}

TEST(GoldenNoise, BackgroundFalseActivation) {
  const LsConventionalConfig cfg = test::preset_config();
  // Tracking threshold 10 mV above 1 V of background: noise sqrt(q V / C + kTC^2 + read^2) ~ 2.05 mV,
  // z ~ 4.9 -> ~5e-7 per pixel, ~2e-4 per row of 375: below the 1% limit.
  const double p = pixel_false_activation_probability(cfg, 1.0);
  EXPECT_GT(p, 1e-7);
  EXPECT_LT(p, 3e-6);
  EXPECT_NEAR(row_false_activation_probability(cfg, 1.0), -std::expm1(375 * std::log1p(-p)), 1e-15);
  EXPECT_LT(row_false_activation_probability(cfg, 0.1), 1e-20);
}

// The tabulated band (ActivationTable, what the golden evaluation uses) gives activation_probability's
// bits: the same terms in the same order, the band's Phi looked up instead of computed.
TEST(GoldenNoise, ActivationTableIsActivationProbabilityBitForBit) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0, 1);
  for (int i = 0; i < 300; ++i) {
    const double s = i % 10 == 0 ? 0.0 : std::pow(10.0, 3 * u(rng) - 1);  // 0.1 .. 100 electrons, some 0
    const double t = std::pow(10.0, 6 * u(rng));
    const ActivationTable table(t, s);
    for (double f : {0.5, 0.9, 0.99, 1.0, 1.01, 1.1, 2.0}) {
      const double mu = t * f + (u(rng) - 0.5) * 30;
      const ActivationProbability a = activation_probability(mu, t, s), b = table(mu);
      EXPECT_EQ(a.p, b.p) << mu << " " << t << " " << s;
      EXPECT_EQ(a.q, b.q) << mu << " " << t << " " << s;
    }
  }
}

// The outlier split (position_moments_split): an outlier is an activation outside the spot's pixels
// (golden/common/spot.h). At 1 V background every background pixel fires with P = 5.6e-7, so the
// outlier probability is that of the row's pixels outside the spot's; nothing is detected only if
// neither the spot's pixels nor any other fires (independent pixels). At 0.01 V background no
// pixel outside the spot's may fire: clean and all are the same.
TEST(GoldenNoise, OutlierSplitAtTheSpotsPixels) {
  const LsConventionalConfig cfg = test::preset_config();
  const double p_bg = pixel_false_activation_probability(cfg, 1.0);
  for (double x0 : {187.0, 187.3}) {
    SCOPED_TRACE(x0);
    const RowModel row = make_row_model(cfg, 0.05, 1.0);
    const SplitMoments m = position_moments_split(row, x0);
    const ColumnSpan spot = spot_window(cfg.spot, x0, row.columns);
    const int outside = row.columns - (spot.last - spot.first + 1);
    EXPECT_NEAR(m.p_outlier, -std::expm1(outside * std::log1p(-p_bg)), 1e-6 * m.p_outlier);
    EXPECT_GT(m.p_outlier, 1e-4);
    EXPECT_NEAR(1 - m.all.p_detect, (1 - m.clean.p_detect) * (1 - m.p_outlier), 1e-15);
    EXPECT_EQ(position_moments(row, x0).mean_px, m.all.mean_px);
    // The outliers move the mean and widen the spread of all frames; the clean ones stay at the spot.
    EXPECT_GT(m.all.var_px2, 10 * m.clean.var_px2);
    EXPECT_NEAR(m.clean.mean_px, x0, 0.5);
  }
  const RowModel low = make_row_model(cfg, 0.05, 0.01);
  const SplitMoments m = position_moments_split(low, 187.3);
  EXPECT_EQ(m.p_outlier, 0.0);
  EXPECT_EQ(m.clean.mean_px, m.all.mean_px);
  EXPECT_EQ(m.clean.var_px2, m.all.var_px2);
}

}  // namespace
}  // namespace rangesim::golden
