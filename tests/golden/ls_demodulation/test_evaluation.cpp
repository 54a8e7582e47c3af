// Evaluation of ls-demodulation over the preset grid: reasons, ranges, averaging, detections,
// mirror gain, runtime, input checks.
#include <gtest/gtest.h>

#include <set>
#include <cmath>

#include "core/user_error.h"
#include "golden/common/evaluate_sensor.h"
#include "golden/ls_demodulation/evaluation.h"
#include "test_helpers_demod.h"
#include "golden/ls_demodulation/model.h"

namespace rangesim::golden {
namespace {

// Its speed is measured by `rangesim bench`/the docs, not asserted here (CI machines are noisy).
TEST(DemodEvaluation, PresetGridIsComplete) {
  const EvalResult r = evaluate_ls_demodulation(test::demod_params(), nullptr);
  EXPECT_EQ(r.sensor, "ls-demodulation");
  EXPECT_EQ(r.signal.unit, "A");
  EXPECT_EQ(r.points.size(), r.signal.values.size() * r.background.values.size());
  EXPECT_GT(r.points_detectable, 0);
  std::set<std::string> seen;
  for (const auto& p : r.points) seen.insert(p.detect);
  for (const char* id : {"detectable", "below_threshold", "saturated", "background_activation"})
    EXPECT_TRUE(seen.count(id)) << id;
  EXPECT_TRUE(std::isfinite(r.accuracy_min_m) && std::isfinite(r.accuracy_max_m));
  EXPECT_LT(r.sbr_ratio_min_dB, 0.0);  // detects below the background (the point of the sensor)
  EXPECT_FALSE(r.signal_range.lo_limited_by_grid);
  EXPECT_TRUE(r.background_range.lo_limited_by_grid);
  std::set<std::string> sweeps;
  for (const auto& s : r.sweeps) sweeps.insert(s.id);
  for (const char* id : {"accuracy_vs_mirror_gain", "accuracy_vs_frames", "accuracy_vs_detections",
                         "selectivity_vs_harmonic", "step_settling"})
    EXPECT_TRUE(sweeps.count(id)) << id;
}

TEST(DemodEvaluation, RangeEdgesAreExact) {
  const LsDemodulationConfig cfg = test::demod_cfg();
  const auto axis = log_spaced(cfg.grid.background_min_A, cfg.grid.background_max_A, cfg.grid.background_points);
  const EvalRange br = demod_background_range(cfg, cfg.grid.signal_max_A, axis);
  ASSERT_TRUE(std::isfinite(br.hi));
  EXPECT_TRUE(demod_detectable(cfg, cfg.grid.signal_max_A, br.hi));
  EXPECT_FALSE(demod_detectable(cfg, cfg.grid.signal_max_A, br.hi * (1 + 1e-9)));
  EXPECT_EQ(classify(cfg, cfg.grid.signal_max_A, br.hi * 1.01).detect, DemodDetect::BackgroundActivation);
}

TEST(DemodEvaluation, Reasons) {
  const LsDemodulationConfig cfg = test::demod_cfg();
  EXPECT_EQ(classify(cfg, 1e-12, 1e-12).detect, DemodDetect::BelowThreshold);
  EXPECT_EQ(classify(cfg, 1e-10, 1e-11).detect, DemodDetect::Detectable);
  EXPECT_EQ(classify(cfg, 1e-10, 1e-8).detect, DemodDetect::BackgroundActivation);  // shot noise of the background
  EXPECT_EQ(classify(cfg, 1e-10, 1e-6).detect, DemodDetect::Saturated);             // mismatch residue, common mode
  LsDemodulationConfig strong = cfg;
  strong.suppression.mirror_gain = 10;
  EXPECT_EQ(classify(strong, 1.11e-9, 1e-12).detect, DemodDetect::Saturated);  // integrator swing > V_sat
}

TEST(DemodEvaluation, FramesDivideTheNoiseVariance) {
  const LsDemodulationConfig cfg = test::demod_cfg();
  const double s = 2e-11, b = 1e-10;
  const DemodAccuracy a1 = evaluate_demod_point(cfg, s, b, 1, 1).accuracy;
  const DemodAccuracy a25 = evaluate_demod_point(cfg, s, b, 1, 25).accuracy;
  // accuracy^2 = bias^2 + var / N_p exactly.
  EXPECT_NEAR(a25.accuracy_px * a25.accuracy_px - a25.bias_rms_px * a25.bias_rms_px,
              (a1.accuracy_px * a1.accuracy_px - a1.bias_rms_px * a1.bias_rms_px) / 25, 1e-12);
  EXPECT_LT(a25.accuracy_px, a1.accuracy_px);
}

TEST(DemodEvaluation, DetectionsHelpUntilReadNoise) {
  LsDemodulationConfig cfg = test::demod_cfg();
  cfg.noise.read_noise_V = 2e-3;  // make the frame-common part visible
  const double s = 2e-11, b = 1e-10;
  const double a1 = evaluate_demod_point(cfg, s, b, 1, 1).accuracy.noise_std_px;
  const double a16 = evaluate_demod_point(cfg, s, b, 16, 1).accuracy.noise_std_px;
  const double a256 = evaluate_demod_point(cfg, s, b, 256, 1).accuracy.noise_std_px;
  EXPECT_LT(a16, a1);
  EXPECT_LT(a256, a16);
  cfg.noise.read_noise_V = 0;
  const double b1 = evaluate_demod_point(cfg, s, b, 1, 1).accuracy.noise_std_px;
  const double b256 = evaluate_demod_point(cfg, s, b, 256, 1).accuracy.noise_std_px;
  EXPECT_NEAR(b256, b1 / 16, 0.05 * b1 / 16);  // without it: exactly 1 / sqrt(K) (all decisions detect)
  EXPECT_GT(a256, 1.5 * b256);                 // with it: a floor the decisions cannot average
}

TEST(DemodEvaluation, HigherMirrorGainLowersTheWeakestSignal) {
  LsDemodulationConfig cfg = test::demod_cfg();
  const double b = 1e-13;  // threshold-limited (at higher backgrounds alpha scales the shot noise too)
  const double s1 = min_detectable_signal_A(cfg, b, 1e-15, 1e-8);
  cfg.suppression.mirror_gain = 10;
  const double s10 = min_detectable_signal_A(cfg, b, 1e-15, 1e-8);
  EXPECT_NEAR(s1 / s10, 10.0, 0.5);  // SBR' gains 20 dB (thesis: "the bigger the gain, the higher the SBR'")
}

TEST(DemodEvaluation, InconsistentWindowIsAUserError) {
  ParamSet p = test::demod_params();
  p.mutable_values().at("correlator.cycles").number = 7;
  EXPECT_THROW(ls_demodulation_from_params(p), UserError);
}

}  // namespace
}  // namespace rangesim::golden
