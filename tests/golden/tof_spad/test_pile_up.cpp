// Closed-form first-photon histogram: the textbook formula without carry-over, the shared-TDC
// factor, the dead-time carry-over chain against hand-derived cases, and numerical robustness in
// deep pile-up.
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

#include "golden/tof_spad/pile_up.h"

namespace rangesim::golden::spad {
namespace {

std::vector<double> ramp(int n, double scale) {
  std::vector<double> r(static_cast<size_t>(n));
  for (int i = 0; i < n; ++i) r[static_cast<size_t>(i)] = scale * (1 + 0.5 * std::sin(0.3 * i));
  return r;
}

TEST(SpadPileUp, TextbookFormulaWithoutCarryOver) {
  PileUpInput in;
  in.photons_per_bin = ramp(64, 0.02);
  in.codes = 64;
  const PileUpHistogram h = expected_histogram(in);
  ASSERT_TRUE(h.converged);
  double before = 0;
  for (int i = 0; i < 64; ++i) {
    const double r = in.photons_per_bin[static_cast<size_t>(i)];
    EXPECT_NEAR(h.event_prob[static_cast<size_t>(i)], (1 - std::exp(-r)) * std::exp(-before), 1e-15) << i;
    EXPECT_NEAR(h.armed_prob[static_cast<size_t>(i)], std::exp(-before), 1e-15);
    before += r;
  }
  EXPECT_NEAR(h.our_events_per_cycle, 1 - std::exp(-before), 1e-14);
  EXPECT_DOUBLE_EQ(h.cycles_per_live_cycle, 1.0);
}

TEST(SpadPileUp, SharedTdcScalesRatesAndShares) {
  PileUpInput in;
  in.photons_per_bin = ramp(32, 0.01);
  in.codes = 32;
  in.share = 4;
  const PileUpHistogram h = expected_histogram(in);
  double before = 0;
  for (int i = 0; i < 32; ++i) {
    const double r = 4 * in.photons_per_bin[static_cast<size_t>(i)];
    EXPECT_NEAR(h.event_prob[static_cast<size_t>(i)], (1 - std::exp(-r)) * std::exp(-before) / 4, 1e-15);
    before += r;
  }
  EXPECT_DOUBLE_EQ(tdc_share(4, 1.0), 4.0);
  EXPECT_DOUBLE_EQ(tdc_share(4, 0.0), 1.0);
}

// One echo bin only, blocking of exactly 4 periods: a hit re-arms at the same phase 4 cycles
// later, so per live cycle P(hit) = q and a live cycle costs 1 + 3 q cycles on average.
TEST(SpadPileUp, CarryOverOfWholePeriods) {
  PileUpInput in;
  in.photons_per_bin.assign(100, 0.0);
  in.photons_per_bin[40] = 0.3;
  in.codes = 100;
  in.block_event_bins = 400;
  const PileUpHistogram h = expected_histogram(in);
  const double q = 1 - std::exp(-0.3);
  EXPECT_NEAR(h.cycles_per_live_cycle, 1 + 3 * q, 1e-12);
  EXPECT_NEAR(h.event_prob[40], q / (1 + 3 * q), 1e-12);
  EXPECT_NEAR(h.armed_prob[40], 1 / (1 + 3 * q), 1e-12);
}

// Blocking that ends at phase 50 of the next cycle: an echo at bin 40 is missed in the cycle
// after a hit. Live cycles alternate: from 0 (hit prob q) and from 50 (no hit possible).
TEST(SpadPileUp, CarryOverIntoTheEchoOfTheNextCycle) {
  PileUpInput in;
  in.photons_per_bin.assign(100, 0.0);
  in.photons_per_bin[40] = 0.5;
  in.codes = 100;
  in.block_event_bins = 110;  // 40 + 110 = 150 -> next cycle, armed from bin 50
  const PileUpHistogram h = expected_histogram(in);
  const double q = 1 - std::exp(-0.5);
  // Per physical cycle: a hit cycle is followed by one cycle armed only after the echo.
  EXPECT_NEAR(h.our_events_per_cycle, q / (1 + q), 1e-12);
  // Late in the cycle only the cycles that have not stopped are armed: 1 - q of those from START
  // and all of those armed from bin 50.
  EXPECT_NEAR(h.armed_prob[60], 1 / (1 + q), 1e-12);
}

TEST(SpadPileUp, DeepPileUpStaysFinite) {
  PileUpInput in;
  in.photons_per_bin.assign(256, 50.0);  // 50 photons per bin: exp(-12800) underflows
  in.codes = 256;
  in.share = 4;
  in.block_event_bins = 1024;
  const PileUpHistogram h = expected_histogram(in);
  EXPECT_TRUE(h.converged);
  double sum = 0;
  for (double p : h.event_prob) {
    EXPECT_TRUE(std::isfinite(p));
    sum += p;
  }
  EXPECT_LE(sum, 1.0);
  // Every live cycle stops in bin 0 and blocks 4 whole cycles: one TDC event per 4 cycles, ours
  // one in 4 of them.
  EXPECT_NEAR(h.event_prob[0], 1.0 / 16, 1e-12);
  EXPECT_NEAR(h.cycles_per_live_cycle, 4.0, 1e-12);
}

}  // namespace
}  // namespace rangesim::golden::spad
