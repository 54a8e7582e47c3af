// Confidence intervals of the Monte Carlo statistics and their exact journal records.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "app/montecarlo/mc_stats.h"

namespace rangesim::app::mc {
namespace {

TEST(McStats, WilsonIntervalKnownValues) {
  // 8 of 10: Wilson 95% interval [0.4902, 0.9433] (textbook value).
  const McInterval w = wilson_interval(8, 10);
  EXPECT_NEAR(w.value, 0.8, 1e-12);
  EXPECT_NEAR(w.lo, 0.4902, 1e-4);
  EXPECT_NEAR(w.hi, 0.9433, 1e-4);
  const McInterval all = wilson_interval(50, 50);
  EXPECT_EQ(all.hi, 1.0);
  EXPECT_GT(all.lo, 0.9);
}

TEST(McStats, MomentsOfAKnownSample) {
  const std::vector<double> e = {1, 2, 3, 4};
  const McPointStats s = summarise_trials(5, e);
  EXPECT_EQ(s.trials, 5);
  EXPECT_EQ(s.detected, 4);
  EXPECT_DOUBLE_EQ(s.bias.value, 2.5);
  EXPECT_DOUBLE_EQ(s.std.value, std::sqrt(5.0 / 3.0));  // sample variance 1.6667
  EXPECT_DOUBLE_EQ(s.rms.value, std::sqrt(7.5));
  EXPECT_NEAR(s.bias.half_width(), kZ95 * std::sqrt(5.0 / 3.0 / 4.0), 1e-12);
  EXPECT_LT(s.rms.lo, s.rms.value);
  EXPECT_GT(s.rms.hi, s.rms.value);
  EXPECT_TRUE(std::isnan(summarise_trials(3, {1.0}).rms.value));  // one detection: no interval
}

// The intervals cover: over 400 repetitions of 200 normal draws (mean 0.3, sd 2) the 95%
// intervals of mean, std and rms contain the truth 95% +- 3 binomial standard errors (3.3%).
TEST(McStats, IntervalsCoverTheTruth) {
  std::mt19937_64 rng(12345);
  std::normal_distribution<double> d(0.3, 2.0);
  int cover_mean = 0, cover_std = 0, cover_rms = 0;
  const int reps = 400;
  for (int r = 0; r < reps; ++r) {
    std::vector<double> e(200);
    for (double& x : e) x = d(rng);
    const McPointStats s = summarise_trials(200, e);
    cover_mean += s.bias.contains(0.3);
    cover_std += s.std.contains(2.0);
    cover_rms += s.rms.contains(std::sqrt(0.09 + 4.0));
  }
  const double tol = 3 * std::sqrt(0.95 * 0.05 / reps);
  EXPECT_NEAR(cover_mean / double(reps), 0.95, tol);
  EXPECT_NEAR(cover_std / double(reps), 0.95, tol);
  EXPECT_NEAR(cover_rms / double(reps), 0.95, tol);
}

// The clean rms leaves out exactly the flagged trials: with no flag (or an all-false flag vector)
// it is the rms of all trials bit for bit; with flags, the rms of the others.
TEST(McStats, CleanRmsLeavesOutTheOutliersOnly) {
  const std::vector<double> e = {0.5, -1.25, 3.0, 0.125, -0.75};
  const McPointStats none = summarise_trials(6, e), unflagged = summarise_trials(6, e, {0, 0, 0, 0, 0});
  EXPECT_EQ(none.outliers, 0);
  EXPECT_EQ(none.rms_clean.value, none.rms.value);
  EXPECT_EQ(none.rms_clean.lo, none.rms.lo);
  EXPECT_EQ(none.rms_clean.hi, none.rms.hi);
  EXPECT_EQ(unflagged.to_record(), none.to_record());
  const McPointStats flagged = summarise_trials(6, e, {0, 0, 1, 0, 0});
  EXPECT_EQ(flagged.outliers, 1);
  EXPECT_EQ(flagged.rms.value, none.rms.value);
  EXPECT_DOUBLE_EQ(flagged.rms_clean.value, summarise_trials(4, {0.5, -1.25, 0.125, -0.75}).rms.value);
  EXPECT_LT(flagged.rms_clean.value, flagged.rms.value);
}

TEST(McStats, RecordRoundTripIsExact) {
  const McPointStats s = summarise_trials(1000, {0.1, -0.2, 1.0 / 3.0, 1e-300, 7.25});
  const McPointStats t = McPointStats::from_record(s.to_record());
  EXPECT_EQ(t.to_record(), s.to_record());
  EXPECT_EQ(t.trials, 1000);
  EXPECT_EQ(t.rms.value, s.rms.value);  // bit for bit
  EXPECT_EQ(t.std.lo, s.std.lo);
  const McPointStats n = McPointStats::from_record(summarise_trials(2, {}).to_record());
  EXPECT_TRUE(std::isnan(n.bias.value));
  EXPECT_THROW(McPointStats::from_record("12 x"), std::runtime_error);
}

}  // namespace
}  // namespace rangesim::app::mc
