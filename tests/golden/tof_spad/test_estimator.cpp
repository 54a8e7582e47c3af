// The range estimator: window placement, the estimator on a histogram, its closed-form moments
// against Thompson's formula where Thompson's assumptions hold, and Coates against raw counts.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "golden/tof_spad/point_model.h"
#include "spad_test_helpers.h"

namespace rangesim::golden::spad {
namespace {

constexpr double kHalfC = 299792458.0 / 2;

// An ideal TDC (no INL/DNL) and a 50 ms histogram: Thompson's setting.
TofSpadConfig ideal_config() {
  TofSpadConfig cfg = test::preset_config();
  cfg.tdc.inl_rms_lsb = 0;
  cfg.tdc.dnl_rms_lsb = 0;
  return cfg;
}

TEST(SpadEstimator, WindowStaysInsideTheCodes) {
  const Window mid = peak_window(100, 7, 256);
  EXPECT_EQ(mid.lo, 97);
  EXPECT_EQ(mid.hi, 103);
  const Window even = peak_window(100, 6, 256);  // one more bin before the peak
  EXPECT_EQ(even.lo, 97);
  EXPECT_EQ(even.hi, 102);
  EXPECT_EQ(peak_window(1, 7, 256).lo, 0);
  EXPECT_EQ(peak_window(255, 7, 256).hi, 255);
  EXPECT_EQ(peak_window(255, 7, 256).lo, 249);
}

TEST(SpadEstimator, NothingDetectedIsExplicit) {
  const SpadModel m(ideal_config());
  HistogramCounts h{std::vector<double>(256, 0.0), std::vector<double>(256, 1000.0), 4.0};
  EXPECT_FALSE(estimate_time_s(h, m.bins(), m.estimator()).has_value());  // no events
  h.events.assign(256, 3.0);  // flat: nothing above the background in the window
  EXPECT_FALSE(estimate_time_s(h, m.bins(), {7, false, true}).has_value());
}

TEST(SpadEstimator, ExpectedHistogramGivesTheRoundTripTime) {
  const SpadModel m(ideal_config());
  for (double d : {0.8, 1.234, 2.5, 3.6}) {
    const PileUpHistogram p = m.histogram(1e5, 1e4, d);
    HistogramCounts h{{}, {}, m.share()};
    for (size_t i = 0; i < p.event_prob.size(); ++i) {
      h.events.push_back(m.cycles() * p.event_prob[i]);
      h.armed.push_back(m.cycles() * p.armed_prob[i]);
    }
    const double t0 = 2 * d / 299792458.0;
    for (bool coates : {true, false}) {
      const auto t = estimate_time_s(h, m.bins(), {7, coates, true});
      ASSERT_TRUE(t.has_value());
      // Centroid of a Gaussian (sigma 0.75 LSB) sampled at bin centres: < 0.1 ps off. Without
      // Coates pile-up skews the echo early by a little.
      EXPECT_NEAR(*t, t0, coates ? 0.1e-12 : 0.5e-12) << d << " coates " << coates;
    }
  }
}

// Thompson et al. 2002 (golden/tof_spad/estimator.h) holds for negligible pile-up, a Gaussian IRF and uniform
// background. With few background counts per bin the windowed centroid reaches it: (s^2 +
// a^2/12) / N is the variance of the bin centres of the detected photons. Tolerance 3%.
TEST(SpadEstimator, VarianceMatchesThompsonAtLowCountRates) {
  TofSpadConfig cfg = ideal_config();
  const SpadModel m(cfg);
  const double s = irf_sigma_s(cfg), a = m.bins().lsb_s;
  for (double signal_Hz : {2e3, 2e4, 2e5}) {
    for (bool coates : {true, false}) {
      const PointResult p = m.evaluate(signal_Hz, 10, 2.0, {7, coates, true});
      ASSERT_EQ(p.detect, "detectable");
      const double thompson_m = kHalfC * thompson_sigma_t_s(s, a, p.signal_counts, p.background_per_bin);
      std::printf(
          "Thompson check: signal %g/s (%s), N = %.1f, b = %.4f/bin: ours %.4f mm, Thompson %.4f mm, "
          "ratio %.4f\n",
          signal_Hz, coates ? "Coates" : "raw", p.signal_counts, p.background_per_bin, p.std_m * 1e3, thompson_m * 1e3,
          p.std_m / thompson_m);
      EXPECT_NEAR(p.std_m / thompson_m, 1.0, 0.03) << signal_Hz;
    }
  }
}

// With many background counts per bin Thompson's formula assumes a fit of the Gaussian; the
// windowed centroid weighs the background of every window bin by its squared distance from the
// echo and is worse. Pinned at our value (uniform background, pile-up below 1%).
TEST(SpadEstimator, CentroidIsWorseThanThompsonUnderBackground) {
  TofSpadConfig cfg = ideal_config();
  const SpadModel m(cfg);
  const PointResult p = m.evaluate(2e4, 1e5, 2.0, {7, true, true});
  const double thompson_m =
      kHalfC * thompson_sigma_t_s(irf_sigma_s(cfg), m.bins().lsb_s, p.signal_counts, p.background_per_bin);
  std::printf("Thompson under background: N = %.1f, b = %.2f/bin: ours %.4f mm, Thompson %.4f mm, ratio %.3f\n",
              p.signal_counts, p.background_per_bin, p.std_m * 1e3, thompson_m * 1e3, p.std_m / thompson_m);
  EXPECT_NEAR(p.std_m / thompson_m, 1.30, 0.05);
}

TEST(SpadEstimator, CoatesEqualsRawWithoutPileUp) {
  const SpadModel m(ideal_config());
  const PointResult c = m.evaluate(1e3, 10, 3.0, {7, true, true});
  const PointResult r = m.evaluate(1e3, 10, 3.0, {7, false, true});
  EXPECT_NEAR(c.std_m / r.std_m, 1.0, 0.01);
  EXPECT_NEAR(c.bias_m, r.bias_m, 0.05e-3);
}

// Without carry-over (10 ns dead and busy time) a strong echo piles up: the first photon comes
// early in the pulse and the raw centroid moves early by mm (the dead time is no whole number of
// periods: no SPAD recharges onto a later echo). Coates inverts the hazard of the recorded first
// avalanche: without jitter that is the arrivals' and the skew goes entirely (the bias is that
// of a weak echo); with the jitter
// after the first photon (timing_jitter.h) the recorded hazard is the first photon's law
// convolved with the jitter, not the arrivals', and Coates leaves about an eighth of the skew,
// late (pinned: 0.33 mm against -2.74 mm raw).
TEST(SpadEstimator, CoatesRemovesThePileUpSkewOfTheEcho) {
  TofSpadConfig cfg = ideal_config();
  cfg.tdc.busy_time_s = cfg.spad.dead_time_s = 10e-9;
  const SpadModel m(cfg);
  const PointResult c = m.evaluate(1e7, 1e3, 3.0, {7, true, true});
  const PointResult r = m.evaluate(1e7, 1e3, 3.0, {7, false, true});
  std::printf("10 ns dead and busy time, 1e7/s echo: bias Coates %.4f mm, raw %.4f mm\n", c.bias_m * 1e3,
              r.bias_m * 1e3);
  EXPECT_NEAR(c.bias_m, 0.328e-3, 0.005e-3);
  EXPECT_NEAR(r.bias_m, -2.742e-3, 0.02e-3);
  EXPECT_LT(c.accuracy_m, r.accuracy_m / 8);
  cfg.spad.jitter_sigma_s = 0;
  const SpadModel no_jitter(cfg);
  const PointResult c0 = no_jitter.evaluate(1e7, 1e3, 3.0, {7, true, true});
  const PointResult r0 = no_jitter.evaluate(1e7, 1e3, 3.0, {7, false, true});
  // Without jitter the echo (the pulse alone, 0.44 LSB) is narrow against the bins: the centroid
  // keeps a quantisation bias, the same as without pile-up (a weak echo).
  const PointResult weak = no_jitter.evaluate(1e4, 1e3, 3.0, {7, true, true});
  std::printf("the same without jitter: bias Coates %.4f mm (weak echo %.4f mm), raw %.4f mm\n", c0.bias_m * 1e3,
              weak.bias_m * 1e3, r0.bias_m * 1e3);
  EXPECT_NEAR(c0.bias_m, weak.bias_m, 0.01e-3);
  EXPECT_LT(std::fabs(c0.bias_m - weak.bias_m), std::fabs(r0.bias_m - weak.bias_m) / 50);
}

// With the preset the TDC group is blind for 100 ns = 4 periods after a hit and re-arms at the
// phase of that hit: cycles after an early-echo hit miss the early echo, which skews late and all
// but cancels the pile-up skew of the raw histogram (-2.7 mm without carry-over, above). The dead
// time of 2 periods puts a SPAD that fired on an echo back on the echo two periods later,
// recharging within the pulse: Coates, which takes the hazard of an armed TDC as the arrivals',
// keeps that skew, and the jitter after the first photon adds its own (above): a quarter of a mm
// late at 10 Mcounts/s, pinned; SpadGolden.EstimatorMomentsCoatesStrongEcho compares it with the
// kernel.
TEST(SpadEstimator, PhaseLockedReArmHidesThePileUpSkew) {
  const SpadModel m(ideal_config());
  const PointResult c = m.evaluate(1e7, 1e3, 3.0, {7, true, true});
  const PointResult r = m.evaluate(1e7, 1e3, 3.0, {7, false, true});
  std::printf("preset, 1e7/s echo: bias Coates %.4f mm, raw %.4f mm\n", c.bias_m * 1e3, r.bias_m * 1e3);
  EXPECT_NEAR(c.bias_m, 0.2572e-3, 0.005e-3);
  EXPECT_NEAR(r.bias_m, 0.2677e-3, 0.005e-3);
  EXPECT_LT(std::fabs(c.bias_m), 0.3e-3);  // still a tenth of the mm-scale pile-up skew
}

TEST(SpadEstimator, PlainCentroidIsPulledToTheWindowCentre) {
  const SpadModel m(ideal_config());
  // The thesis's eq. 4.19 without background subtraction: background counts in the window pull
  // the estimate towards the window's centre, which the peak bin places within half a bin.
  const PointResult plain = m.evaluate(2e3, 3e5, 1.7, {7, false, false});
  const PointResult sub = m.evaluate(2e3, 3e5, 1.7, {7, false, true});
  EXPECT_GT(std::fabs(plain.bias_m), 3 * std::fabs(sub.bias_m));
}

}  // namespace
}  // namespace rangesim::golden::spad
