// Centroid, edge centre and the noise-free multi-sampling estimate with its exact error integral.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>

#include "golden/ls_conventional/centroid.h"
#include "golden/ls_conventional/multisampling.h"
#include "golden/common/row_model.h"
#include "test_helpers.h"

namespace rangesim::golden {
namespace {

TEST(GoldenCentroid, HandValues) {
  const std::vector<double> x{10, 11, 12, 13};
  // (1*10 + 3*11 + 0*12 + 0*13) / 4 = 10.75 (the thesis's sum(x_i) denominator would give 0.93).
  const CentreEstimate c = weighted_centroid(x, {1, 3, 0, 0});
  ASSERT_TRUE(c.detected);
  EXPECT_DOUBLE_EQ(c.centre_px, 10.75);
  const CentreEstimate e = edge_centre(x, {false, true, false, true});
  ASSERT_TRUE(e.detected);
  EXPECT_DOUBLE_EQ(e.centre_px, 12.0);  // (11 + 13) / 2
  const CentreEstimate m = mean_of_detections({{true, 10.0}, {false, 0.0}, {true, 11.0}});
  ASSERT_TRUE(m.detected);
  EXPECT_DOUBLE_EQ(m.centre_px, 10.5);
}

TEST(GoldenCentroid, NothingDetected) {
  const std::vector<double> x{0, 1, 2};
  EXPECT_FALSE(weighted_centroid(x, {0, 0, 0}).detected);
  EXPECT_FALSE(edge_centre(x, {false, false, false}).detected);
  EXPECT_FALSE(mean_of_detections({{false, 0}, {false, 0}}).detected);
  EXPECT_FALSE(mean_of_detections({}).detected);
}

TEST(GoldenCentroid, SymmetricSpotGivesItsCentre) {
  std::vector<double> x, w;
  for (int i = 0; i < 21; ++i) {
    x.push_back(i);
    w.push_back(std::exp(-(i - 10.0) * (i - 10.0) / 8.0));
  }
  EXPECT_NEAR(weighted_centroid(x, w).centre_px, 10.0, 1e-12);
  // And through the sensor model: a spot centred on a pixel, any bits / samplings.
  for (int bits : {1, 2, 4})
    for (int N : {1, 4}) {
      LsConventionalConfig cfg = test::preset_config();
      cfg.comparator.adc_bits = bits;
      cfg.multisampling.samplings = N;
      const RowModel row = make_row_model(cfg, 0.3, 0.01);
      const CentreEstimate c = noise_free_estimate(row, row.centre_pixel);
      ASSERT_TRUE(c.detected);
      EXPECT_NEAR(c.centre_px, row.centre_pixel, 1e-12) << bits << " bits, " << N << " samplings";
      // Half-way between two pixels is symmetric too.
      EXPECT_NEAR(noise_free_estimate(row, row.centre_pixel + 0.5).centre_px, row.centre_pixel + 0.5, 1e-12);
    }
}

TEST(GoldenMultisampling, HalfWidthsByHand) {
  LsConventionalConfig cfg = test::preset_config();
  cfg.multisampling.samplings = 2;
  cfg.pixel.dark_current_A = 0;
  const RowModel row = make_row_model(cfg, 0.04, 0.001);
  // theta = 0.011. k = 2 (t = T): 0.04 g + 0.001 >= 0.011 -> g >= 0.25; k = 1: 0.04 g + 0.001 >= 0.022
  // -> g >= 0.525. h = sigma sqrt(-2 ln g), sigma = 3 * 0.42466.
  const double sigma = 3 * 0.42466090014400953;
  EXPECT_NEAR(row.half_width_px[1][0], sigma * std::sqrt(-2 * std::log(0.25)), 1e-12);
  EXPECT_NEAR(row.half_width_px[0][0], sigma * std::sqrt(-2 * std::log(0.525)), 1e-12);
  // Hand estimate at x0 = c + 0.3: h2 = 2.12 -> pixels c-1..c+2, centre c+0.5; h1 = 1.44 -> c-1..c+1,
  // centre c. Mean c + 0.25.
  const CentreEstimate e = noise_free_estimate(row, row.centre_pixel + 0.3);
  ASSERT_TRUE(e.detected);
  EXPECT_NEAR(e.centre_px, row.centre_pixel + 0.25, 1e-12);
}

TEST(GoldenMultisampling, AnalyticMatchesBruteForce) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-0.5, 0.5);
  for (int bits : {1, 2, 3})
    for (int N : {1, 3, 4})
      for (double sig : {0.0105, 0.05, 0.4, 1.2}) {
        LsConventionalConfig cfg = test::preset_config();
        cfg.comparator.adc_bits = bits;
        cfg.multisampling.samplings = N;
        const RowModel row = make_row_model(cfg, sig, 0.02);
        for (int i = 0; i < 20; ++i) {
          const double x0 = row.centre_pixel + u(rng);
          const CentreEstimate a = noise_free_estimate(row, x0), b = direct_estimate(row, x0);
          ASSERT_EQ(a.detected, b.detected);
          if (a.detected) {
            EXPECT_NEAR(a.centre_px, b.centre_px, 1e-9);
          }
        }
      }
}

TEST(GoldenMultisampling, NothingDetectedNearThreshold) {
  // Just above threshold the activated half-width is < 0.5 px: a spot centred between two pixels
  // activates none of them. The estimate says so explicitly, and the error integral leaves it out.
  LsConventionalConfig cfg = test::preset_config();
  const RowModel row = make_row_model(cfg, 0.01002, 0.001);
  ASSERT_GE(row.half_width_px.back()[0], 0);
  ASSERT_LT(row.half_width_px.back()[0], 0.5);
  EXPECT_TRUE(noise_free_estimate(row, row.centre_pixel).detected);
  EXPECT_FALSE(noise_free_estimate(row, row.centre_pixel + 0.5).detected);
  const QuantisationError q = quantisation_error(row);
  EXPECT_NEAR(q.detected_fraction, 2 * row.half_width_px.back()[0], 1e-12);
  EXPECT_NEAR(q.worst_px, row.half_width_px.back()[0], 1e-12);
  // Below threshold nothing ever activates.
  const RowModel dark = make_row_model(cfg, 0.005, 0.001);
  EXPECT_FALSE(noise_free_estimate(dark, dark.centre_pixel).detected);
  EXPECT_EQ(quantisation_error(dark).detected_fraction, 0);
}

// Mean square error by brute force: dense midpoint sampling of x0 across the pixel.
double brute_rms(const RowModel& row, int n) {
  double s = 0;
  int d = 0;
  for (int i = 0; i < n; ++i) {
    const double x0 = row.centre_pixel - 0.5 + (i + 0.5) / n;
    const CentreEstimate c = noise_free_estimate(row, x0);
    if (!c.detected) continue;
    s += (c.centre_px - x0) * (c.centre_px - x0);
    ++d;
  }
  return std::sqrt(s / d);
}

TEST(GoldenMultisampling, ExactErrorIntegralMatchesDenseSampling) {
  for (int bits : {1, 3})
    for (double sig : {0.02, 0.3, 1.4}) {
      LsConventionalConfig cfg = test::preset_config();
      cfg.comparator.adc_bits = bits;
      const RowModel row = make_row_model(cfg, sig, 0.01);
      const QuantisationError q = quantisation_error(row);
      EXPECT_NEAR(q.rms_px, brute_rms(row, 200000), 2e-5) << bits << " bits, signal " << sig;
      EXPECT_NEAR(q.equivalent_step_px, std::sqrt(12.0) * q.rms_px, 1e-15);
    }
}

TEST(GoldenMultisampling, SingleSamplingStepIsHalfPixel) {
  // With one sampling the readout is binary and (l + r) / 2 moves in steps of exactly 0.5 px
  // (thesis 2.1, Fig. 2.3a): resolution (mean step) 0.5 px. The rms-equivalent step
  // sqrt(12) rms equals 0.5 only when the left and right edges switch half a pixel apart
  // (frac(h) = 1/4 or 3/4); in general it is sqrt(delta^3 + (1 - delta)^3) for switch points
  // delta apart.
  LsConventionalConfig cfg = test::preset_config();
  cfg.multisampling.samplings = 1;
  for (double sig : {0.015, 0.05, 0.1, 0.3, 0.7, 1.5}) {
    const RowModel row = make_row_model(cfg, sig, 0.001);
    const QuantisationError q = quantisation_error(row);
    EXPECT_DOUBLE_EQ(q.largest_step_px, 0.5) << sig;
    EXPECT_DOUBLE_EQ(q.resolution_px, 0.5) << sig;
    const double h = row.half_width_px[0][0];
    const double delta = std::fabs(1 - 2 * (h - std::floor(h)));
    EXPECT_NEAR(q.equivalent_step_px, std::sqrt(delta * delta * delta + std::pow(1 - delta, 3)), 1e-12) << sig;
    EXPECT_NEAR(q.worst_px, 0.5 * std::max(delta, 1 - delta), 1e-12) << sig;
  }
  // Degenerate case: at 0.02 V over 0.001 V the activated half-width is exactly FWHM / 2 = 1.5 px,
  // both edges switch at the same x0 (the pixel's ends) and the estimate jumps by a whole pixel.
  EXPECT_NEAR(quantisation_error(make_row_model(cfg, 0.02, 0.001)).resolution_px, 1.0, 1e-9);
  // Where the edges switch exactly half a pixel apart the rms-equivalent step is 0.5 px too:
  // h = 1.25 px -> g = exp(-h^2 / (2 sigma^2)) = (theta - V_bg) / V_sig.
  const double sigma = 3 * 0.42466090014400953;
  const double g = std::exp(-1.25 * 1.25 / (2 * sigma * sigma));
  const RowModel row = make_row_model(cfg, 0.01 / g, 0.001);
  EXPECT_NEAR(quantisation_error(row).equivalent_step_px, 0.5, 1e-9);
}

// Resolution (mean step) averaged over signal levels log-uniform across the detectable range
// at 0.001 V background.
double mean_resolution(LsConventionalConfig cfg, int samplings, int bits = 1) {
  cfg.multisampling.samplings = samplings;
  cfg.comparator.adc_bits = bits;
  const int M = 300;
  double s = 0;
  for (int i = 0; i < M; ++i) {
    const double sig = 0.0101 * std::pow(1.5 / 0.0101, (i + 0.5) / M);
    s += quantisation_error(make_row_model(cfg, sig, 0.001)).resolution_px;
  }
  return s / M;
}

TEST(GoldenMultisampling, DoublingSamplingsNeverCoarsens) {
  // The sampling instants of N samplings are a subset of those of 2N, every per-sampling centre
  // is non-decreasing in the spot position, so the jumps of the mean with N samplings are a
  // subset of those with 2N: the resolution can only get finer, at every operating point.
  const LsConventionalConfig base = test::preset_config();
  for (int N : {1, 2, 4, 8})
    for (double sig : {0.0105, 0.02, 0.05, 0.1, 0.3, 0.7, 1.0, 1.5})
      for (double bg : {0.001, 0.03, 0.2}) {
        LsConventionalConfig a = base, b = base;
        a.multisampling.samplings = N;
        b.multisampling.samplings = 2 * N;
        const double ra = quantisation_error(make_row_model(a, sig, bg)).resolution_px;
        const double rb = quantisation_error(make_row_model(b, sig, bg)).resolution_px;
        EXPECT_LE(rb, ra + 1e-12) << N << " -> " << 2 * N << " samplings at " << sig << " V / " << bg << " V";
      }
}

TEST(GoldenMultisampling, MoreSamplingsRefineOnAverage) {
  // From N to N + 1 the instants move (t_k = k T / N), so a single operating point can coarsen;
  // averaged over signal levels it refines at every step.
  const LsConventionalConfig cfg = test::preset_config();
  double prev = 1e9;
  for (int N = 1; N <= 8; ++N) {
    const double r = mean_resolution(cfg, N);
    EXPECT_LT(r, prev) << N;
    prev = r;
  }
}

TEST(GoldenMultisampling, FourSamplingsWithPreset) {
  // Published: 0.5 px sub-pixel resolution without multi-sampling, about 0.2 px with four.
  // With the preset, averaged over the detectable signal levels: 0.50 px and 0.17 px.
  const LsConventionalConfig cfg = test::preset_config();
  EXPECT_NEAR(mean_resolution(cfg, 1), 0.5, 0.01);
  EXPECT_NEAR(mean_resolution(cfg, 4), 0.17, 0.02);
}

TEST(GoldenMultisampling, MoreAdcBitsWorstErrorOverOperatingPoints) {
  // Property asked for: more ADC bits never raise the worst-case error. It does NOT hold point by
  // point in this model: the LSB is fixed at Delta V_ADC (eq. 3.7), so an extra bit does not refine
  // the steps, it only removes the clipping of the top code. A clipped (flat-topped) profile can
  // happen to centre better than the unclipped floor-quantised one, e.g. 1 sampling, 1.5 V signal:
  // worst error 0.090 px with 3 bits, 0.126 px with 4. What holds, and is tested: over a set of
  // operating points the largest worst-case error and the mean worst-case error never rise.
  {
    LsConventionalConfig cfg = test::preset_config();
    cfg.multisampling.samplings = 1;
    cfg.comparator.adc_bits = 3;
    EXPECT_NEAR(quantisation_error(make_row_model(cfg, 1.5, 0.001)).worst_px, 0.0896, 0.001);
    cfg.comparator.adc_bits = 4;
    EXPECT_NEAR(quantisation_error(make_row_model(cfg, 1.5, 0.001)).worst_px, 0.1257, 0.001);
  }
  for (int N : {1, 2, 4}) {
    double prev_max = 1e9, prev_mean = 1e9;
    for (int bits = 1; bits <= 6; ++bits) {
      LsConventionalConfig cfg = test::preset_config();
      cfg.multisampling.samplings = N;
      cfg.comparator.adc_bits = bits;
      double mx = 0, sum = 0;
      int n = 0;
      for (double bg : {0.001, 0.05, 0.2})
        for (int i = 0; i < 60; ++i) {
          const double sig = 0.0105 * std::pow(1.5 / 0.0105, (i + 0.5) / 60);
          const double w = quantisation_error(make_row_model(cfg, sig, bg)).worst_px;
          mx = std::max(mx, w);
          sum += w;
          ++n;
        }
      EXPECT_LE(mx, prev_max + 1e-12) << N << " samplings, " << bits << " bits";
      EXPECT_LE(sum / n, prev_mean + 1e-12) << N << " samplings, " << bits << " bits";
      prev_max = mx;
      prev_mean = sum / n;
    }
  }
}

}  // namespace
}  // namespace rangesim::golden
