// Detect classification, dynamic ranges and the grid evaluation against the thesis's figures
// (chapter 3.1.3, Table 5.1), pinning our values where the thesis's do not follow from its own
// parameters.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>

#include "golden/ls_conventional/detect.h"
#include "golden/ls_conventional/evaluation.h"
#include "golden/common/pixel.h"
#include "golden/common/threshold.h"
#include "test_helpers.h"

namespace rangesim::golden {
namespace {

TEST(GoldenEvaluation, LogAxis) {
  EXPECT_EQ(log_axis(0.5, 2, 1), std::vector<double>{0.5});
  const auto a = log_axis(0.001, 1, 4);
  ASSERT_EQ(a.size(), 4u);
  EXPECT_NEAR(a[1], 0.01, 1e-15);
  EXPECT_NEAR(a[2], 0.1, 1e-15);
  EXPECT_EQ(a[3], 1.0);
}

TEST(GoldenEvaluation, ClassifyOperatingPoints) {
  LsConventionalConfig cfg = test::preset_config();
  EXPECT_EQ(classify(cfg, 0.0099, 0.001), Detect::BelowThreshold);
  EXPECT_EQ(classify(cfg, 0.0101, 0.001), Detect::Detectable);
  EXPECT_EQ(classify(cfg, 1.5, 0.2409), Detect::Detectable);
  EXPECT_EQ(classify(cfg, 1.5, 0.2411), Detect::Saturated);
  EXPECT_EQ(classify(cfg, 0.02, 1.0), Detect::Detectable);  // tracking threshold, noise below the limit
  cfg.comparator.threshold_mode = ThresholdMode::Fixed;     // fixed 11 mV: background alone reaches it
  EXPECT_EQ(classify(cfg, 0.5, 0.02), Detect::BackgroundActivation);
  EXPECT_EQ(classify(cfg, 0.5, 0.005), Detect::Detectable);
  EXPECT_EQ(classify(cfg, 0.003, 0.005), Detect::BelowThreshold);
  // With noise: 3 mV below the fixed threshold the background's noise (0.47 mV rms) stays quiet
  // (6.4 sigma); 1.5 mV below it (3.2 sigma) some pixel of the 375 fires in ~23% of the frames.
  EXPECT_EQ(classify(cfg, 0.5, 0.008), Detect::Detectable);
  EXPECT_EQ(classify(cfg, 0.5, 0.0095), Detect::BackgroundActivation);
  EXPECT_STREQ(to_string(Detect::BackgroundActivation), "background_activation");
}

// The thesis's own point (3.1.3): 0.01 V signal over 0.001 V background, SBR' 20.83 dB. The spot
// peak A (V_sig + V_bg + V_dark) and the tracking threshold A (V_bg + V_dark) + Delta V_ADC are the
// same number computed two ways; before the rounding-tolerant comparison it was classed
// below_threshold by the last bit.
TEST(GoldenEvaluation, ThesisPointAtThresholdIsDetectable) {
  const LsConventionalConfig cfg = test::preset_config();
  EXPECT_EQ(classify(cfg, 0.01, 0.001), Detect::Detectable);
  const OperatingPoint p = evaluate_point(cfg, 0.01, 0.001);
  EXPECT_EQ(p.detect, Detect::Detectable);
  EXPECT_NEAR(p.sbr_total_dB, 20.83, 0.005);
  EXPECT_GT(p.accuracy_px, 0.0);  // a real accuracy, not the "not detectable" zero
  // Every background of the grid: the weakest detectable signal is Delta V_ADC / A_sf exactly.
  for (double bg : {0.001, 0.0037, 0.02, 0.1, 0.24})
    EXPECT_NE(classify(cfg, cfg.comparator.threshold_above_background_V / cfg.pixel.source_follower_gain, bg),
              Detect::BelowThreshold)
        << bg;
  // A real shortfall (1 ppm below) is still below the threshold.
  EXPECT_EQ(classify(cfg, 0.01 * (1 - 1e-6), 0.001), Detect::BelowThreshold);
}

// The accuracy's average over spot positions is adaptive (evaluation.subpixel_tolerance, Gauss-
// Kronrod between the noise-free breakpoints): the adaptive rule meets its error estimate and lands
// within 0.3 % of a 3888-position midpoint rule (whose own error is about 0.1 %) at (0.12 V,
// 0.002 V), where the former fixed 16-position rule was 15 % low against the Monte Carlo. The fixed
// rule (subpixel_tolerance 0) is the plain average of p and p (b^2 + v) now: 16 positions are
// within 1 % here, but nothing estimates its error. The preset's row is symmetric, so the fixed
// rules evaluate half their positions.
TEST(GoldenEvaluation, AdaptiveSubpixelAverageConverges) {
  LsConventionalConfig cfg = test::preset_config();
  const double tolerance = cfg.grid.subpixel_tolerance;
  ASSERT_GT(tolerance, 0.0);
  const OperatingPoint adaptive = evaluate_point(cfg, 0.12, 0.002);
  cfg.grid.subpixel_tolerance = 0;  // fixed rules
  cfg.grid.subpixel_points = 3888;
  const OperatingPoint ref = evaluate_point(cfg, 0.12, 0.002);
  cfg.grid.subpixel_points = 16;
  const OperatingPoint fixed16 = evaluate_point(cfg, 0.12, 0.002);
  EXPECT_EQ(ref.subpixel_positions, 1944);
  EXPECT_EQ(fixed16.subpixel_positions, 8);
  EXPECT_FALSE(fixed16.subpixel_converged);
  EXPECT_TRUE(adaptive.subpixel_converged);
  EXPECT_LE(adaptive.subpixel_error_estimate, tolerance);
  EXPECT_NEAR(adaptive.accuracy_px, ref.accuracy_px, 0.003 * ref.accuracy_px);
  EXPECT_NEAR(adaptive.p_detect, 1.0, 1e-12);
  EXPECT_NEAR(fixed16.accuracy_px, ref.accuracy_px, 0.01 * ref.accuracy_px);
}

// The average is weighted by P(detect) at every spot position: at the detection edge (the thesis's
// point, noise decides every frame) and with outliers (1 V background) the adaptive rule agrees with
// a 3888-position midpoint rule on P(detect), P(outlier) and both accuracies.
TEST(GoldenEvaluation, AdaptiveAverageAtTheEdgeAndWithOutliers) {
  LsConventionalConfig cfg = test::preset_config();
  for (auto [sig, bg] : {std::pair{0.01, 0.001}, std::pair{0.0272407, 1.0}}) {
    SCOPED_TRACE(bg);
    cfg.grid.subpixel_tolerance = 1e-3;
    const OperatingPoint a = evaluate_point(cfg, sig, bg);
    cfg.grid.subpixel_tolerance = 0;
    cfg.grid.subpixel_points = 3888;
    const OperatingPoint ref = evaluate_point(cfg, sig, bg);
    ASSERT_EQ(a.detect, Detect::Detectable);
    EXPECT_TRUE(a.subpixel_converged);
    EXPECT_NEAR(a.p_detect, ref.p_detect, 1e-3 * ref.p_detect);
    EXPECT_NEAR(a.p_outlier, ref.p_outlier, 1e-3 * ref.p_outlier + 1e-15);
    EXPECT_NEAR(a.accuracy_px, ref.accuracy_px, 3e-3 * ref.accuracy_px);
    EXPECT_NEAR(a.accuracy_clean_px, ref.accuracy_clean_px, 3e-3 * ref.accuracy_clean_px);
  }
  cfg.grid.subpixel_tolerance = 1e-3;
  const OperatingPoint edge = evaluate_point(cfg, 0.01, 0.001);
  EXPECT_TRUE(edge.noise_only_detections);
  EXPECT_GT(edge.p_detect, 0.2);
  EXPECT_LT(edge.p_detect, 0.5);
  const OperatingPoint bright = evaluate_point(cfg, 0.0272407, 1.0);
  EXPECT_GT(bright.p_outlier, 1e-4);
  EXPECT_GT(bright.accuracy_px, 3 * bright.accuracy_clean_px);
}

TEST(ThresholdCompare, ToleratesRoundingOnly) {
  EXPECT_TRUE(reaches_threshold(0.1 + 0.2, 0.3));  // 0.30000000000000004
  EXPECT_TRUE(reaches_threshold(0.3, 0.1 + 0.2));  // 0.3 < 0.30000000000000004 by 1 ulp
  EXPECT_FALSE(below_threshold(0.3, 0.1 + 0.2));
  EXPECT_TRUE(below_threshold(0.3 * (1 - 1e-7), 0.3));  // 100x the tolerance
  EXPECT_FALSE(reaches_threshold(-1e-3, 0.0));
  EXPECT_TRUE(reaches_threshold(0.0, 0.0));
}

TEST(GoldenEvaluation, SignalRangeThesis435dB) {
  // Thesis 3.1.3: detectable signal 0.01-1.5 V at 0.001 V background = 20 log10(150) = 43.5 dB.
  const LsConventionalConfig cfg = test::preset_config();
  const DynamicRange r = signal_dynamic_range(cfg, 0.001, cfg.grid.signal_min_V, cfg.grid.signal_max_V);
  EXPECT_NEAR(r.lo_V, 0.01, 1e-12);
  EXPECT_DOUBLE_EQ(r.hi_V, 1.5);
  EXPECT_TRUE(r.hi_limited_by_grid);  // saturation would allow 1.74 V
  EXPECT_FALSE(r.lo_limited_by_grid);
  EXPECT_NEAR(r.range_dB, 43.52, 0.01);
}

TEST(GoldenEvaluation, BackgroundRangeOursVsThesis) {
  // Thesis: background 0.001-0.241 V at 1.5 V signal (we reproduce it: V_sat - V_sig - V_dark), but
  // it then quotes a 63.5 dB background span, which is 20 log10(1.5 / 0.001): the maximum SIGNAL over
  // the minimum background. The span of the quoted interval is 20 log10(0.241 / 0.001) = 47.6 dB.
  const LsConventionalConfig cfg = test::preset_config();
  const DynamicRange r = background_dynamic_range(cfg, 1.5, cfg.grid.background_min_V, cfg.grid.background_max_V);
  EXPECT_DOUBLE_EQ(r.lo_V, 0.001);
  EXPECT_TRUE(r.lo_limited_by_grid);
  EXPECT_NEAR(r.hi_V, 1.741 - 1.5 - dark_voltage_V(cfg.pixel), 1e-12);
  EXPECT_FALSE(r.hi_limited_by_grid);
  EXPECT_NEAR(r.range_dB, 47.64, 0.01);
  EXPECT_NEAR(20 * std::log10(1.5 / 0.001), 63.5, 0.05);  // how the thesis's number arises
}

TEST(GoldenEvaluation, BackgroundRangeNoiseEdgeFixedThreshold) {
  // Fixed threshold: the upper background edge is where P(any background pixel fires) = limit.
  LsConventionalConfig cfg = test::preset_config();
  cfg.comparator.threshold_mode = ThresholdMode::Fixed;
  const DynamicRange r = background_dynamic_range(cfg, 0.5, 1e-4, 1.0);
  ASSERT_GT(r.range_dB, 0);
  EXPECT_NEAR(row_false_activation_probability(cfg, r.hi_V), cfg.comparator.false_activation_max, 1e-6);
  EXPECT_LT(r.hi_V, 0.011);
}

TEST(GoldenEvaluation, OperatingPointFields) {
  const LsConventionalConfig cfg = test::preset_config();
  const OperatingPoint p = evaluate_point(cfg, 0.3, 0.01);
  EXPECT_EQ(p.detect, Detect::Detectable);
  EXPECT_NEAR(p.sbr_total_dB, 20 * std::log10(0.31 / 0.01), 1e-12);
  EXPECT_NEAR(p.sbr_ratio_dB, 20 * std::log10(30.0), 1e-12);
  EXPECT_GT(p.resolution_px, 0.0);
  EXPECT_LE(p.resolution_px, 1.0);
  EXPECT_GE(p.accuracy_px, p.noise_std_px * 0.99);
  EXPECT_GT(p.noise_std_px, 0);
  EXPECT_NEAR(p.p_detect, 1, 1e-9);
  EXPECT_NEAR(p.accuracy_m, p.accuracy_px * 1.1 * 1.1 * 11.25e-6 / (10e-3 * 73.6e-3), 1e-15);
  EXPECT_STREQ(p.noise_method, "exact");
  const OperatingPoint below = evaluate_point(cfg, 0.005, 0.01);
  EXPECT_EQ(below.detect, Detect::BelowThreshold);
  EXPECT_EQ(below.accuracy_px, 0);
}

TEST(GoldenEvaluation, PresetGridSummary) {
  const LsConventionalConfig cfg = test::preset_config();
  static int calls = 0;
  const auto t0 = std::chrono::steady_clock::now();
  const Evaluation ev = evaluate(cfg, [](int, int) { ++calls; });
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  RecordProperty("evaluate_61x61_seconds", std::to_string(seconds));
  const EvaluationSummary& s = ev.summary;
  EXPECT_GT(calls, 0);
  EXPECT_EQ(s.points_total, 61 * 61);
  ASSERT_GT(s.points_detectable, 0);
  EXPECT_EQ(ev.at(0, 0).detect, Detect::BelowThreshold);
  EXPECT_NEAR(s.signal.range_dB, 43.52, 0.01);
  EXPECT_NEAR(s.background.range_dB, 47.64, 0.01);
  // SBR' over the detectable grid. Table 5.1 quotes 0.06 dB min and 51 dB max; ours (eq. 3.11):
  // max 20 log10(1.501 / 0.001) = 63.5 dB at the strongest signal over the weakest background, min at
  // the weakest detectable grid signal (0.0107 V) over the strongest background (1 V): 0.09 dB. The
  // thesis's 51 dB does not follow from its own ranges (0.001 V background, 1.5 V signal detectable).
  EXPECT_NEAR(s.sbr_max_dB, 63.53, 0.01);
  EXPECT_NEAR(s.sbr_min_dB, 0.088, 0.005);
  EXPECT_NEAR(s.sbr_ratio_max_dB, 63.52, 0.01);
  EXPECT_NEAR(s.sbr_ratio_min_dB, -39.4, 0.5);
  // Accuracy: thesis 0.004-0.089 px. Ours includes shot, kTC and read noise and the binary
  // quantisation of the 1-bit readout, which alone is >= 0.1 px rms for 4 samplings at most signals;
  // 0.004 px would need an essentially continuous profile readout. Pinned to our values.
  EXPECT_GT(s.accuracy_min_px, 0.02);
  EXPECT_LT(s.accuracy_min_px, 0.06);
  EXPECT_GT(s.accuracy_max_px, 1.0);
  EXPECT_NEAR(s.range_per_px_m, 1.1 * 1.1 * 11.25e-6 / (10e-3 * 73.6e-3), 1e-15);
  EXPECT_NEAR(s.accuracy_min_m, s.accuracy_min_px * s.range_per_px_m, 1e-15);
  // Every detectable point has sane fields.
  for (const auto& p : ev.points)
    if (p.detect == Detect::Detectable) {
      EXPECT_GT(p.accuracy_px, 0);
      EXPECT_GE(p.p_detect, 0);
      EXPECT_LE(p.p_detect, 1);
    }
}

}  // namespace
}  // namespace rangesim::golden
