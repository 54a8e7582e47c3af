// The tof-spad range-map validity (golden/tof_spad/validity.h): a background-only histogram stays
// far below the 5 sigma rule whatever its peak search picks, an echo of a few counts over it
// passes, and a lone count in an empty histogram does not.
#include <gtest/gtest.h>

#include <random>

#include "golden/tof_spad/validity.h"

namespace sp = rangesim::golden::spad;

namespace {

// `codes` bins armed `cycles` times each, background events Poisson(mean_per_bin).
sp::HistogramCounts background(int codes, double mean_per_bin, std::mt19937_64& rng) {
  sp::HistogramCounts h;
  std::poisson_distribution<int> bg(mean_per_bin);
  for (int i = 0; i < codes; ++i) h.events.push_back(bg(rng)), h.armed.push_back(1e5);
  return h;
}

}  // namespace

TEST(SpadValidity, BackgroundOnlyHistogramsStayInvalid) {
  std::mt19937_64 rng(7);
  const sp::EstimatorConfig cfg;
  int above = 0;
  double worst = 0;
  for (double mean : {0.05, 0.5, 5.0, 50.0})
    for (int trial = 0; trial < 500; ++trial) {
      const sp::PeakSignificance s = sp::peak_significance(background(256, mean, rng), cfg);
      worst = std::max(worst, s.sigma);
      above += s.sigma >= 5;
    }
  EXPECT_EQ(above, 0) << "worst " << worst;
  EXPECT_LT(worst, 4.0);
}

TEST(SpadValidity, AnEchoOverTheBackgroundIsValid) {
  std::mt19937_64 rng(8);
  const sp::EstimatorConfig cfg;
  sp::HistogramCounts h = background(256, 5.0, rng);
  for (int i = 100; i < 104; ++i) h.events[static_cast<std::size_t>(i)] += 15;  // 60 counts over ~35 expected
  const sp::PeakSignificance s = sp::peak_significance(h, cfg);
  EXPECT_GE(s.peak_bin, 100);
  EXPECT_LE(s.peak_bin, 103);
  EXPECT_GT(s.sigma, 5.0);
  EXPECT_NEAR(s.background_counts, 5.0 * 7, 5.0);
}

TEST(SpadValidity, ALoneCountIsNoPeak) {
  sp::HistogramCounts h;
  h.events.assign(256, 0.0), h.armed.assign(256, 1e5);
  h.events[40] = 1;
  EXPECT_LT(sp::peak_significance(h, {}).sigma, 1.0);
  h.events[41] = 2, h.events[42] = 2;  // five counts in one window of an otherwise empty histogram
  EXPECT_GT(sp::peak_significance(h, {}).sigma, 5.0);
  h.events.assign(256, 0.0);
  EXPECT_EQ(sp::peak_significance(h, {}).sigma, 0.0);
}
