// Monte Carlo on the clock-level kernels against the golden closed forms, per sensor.
//
// The stated test: at a detectable operating point, with the random streams of seed 1, the golden
// value lies within twice the Monte Carlo 95% CI half-width (about +-3.9 standard errors) of the
// Monte Carlo estimate, for the mean error (bias) and for the variance (or, where the golden model
// gives the rms over spot positions only, for the rms error). Where the golden model is a
// delta-method approximation (tof-lockin ratio, tof-spad centroid) the variance may also differ
// by the approximation's stated 10 %.
#include <gtest/gtest.h>

#include <cmath>

#include "app/montecarlo/mc_stats.h"
#include "core/physics.h"
#include "core/preset.h"
#include "golden/ls_conventional/evaluation.h"
#include "golden/ls_demodulation/evaluation.h"
#include "golden/common/position_noise.h"
#include "golden/common/row_model.h"
#include "golden/tof_lockin/lockin_point.h"
#include "golden/tof_spad/point_model.h"
#include "systemc/ls_conventional/montecarlo.h"
#include "systemc/ls_demodulation/montecarlo.h"
#include "systemc/tof_lockin/montecarlo.h"
#include "systemc/tof_spad/montecarlo.h"

namespace rangesim::app::mc {
namespace {

using namespace rangesim::mc;  // the sensors' trial models (systemc/<sensor>/montecarlo.h)

McPointStats run(const McModel& m, double signal, double background, long long trials, std::uint64_t index = 0) {
  auto runner = m.point(signal, background, point_key(1, index));
  std::vector<double> errors;
  for (long long t = 0; t < trials; ++t) {
    const McTrial r = runner->trial(t);
    if (r.detected) errors.push_back(r.error);
  }
  return summarise_trials(trials, errors);
}

// golden within 2 CI half-widths of the MC value, plus a relative slack for approximations.
void expect_agrees(const McInterval& mc, double golden, double rel_slack, const char* what) {
  EXPECT_LE(std::fabs(mc.value - golden), 2 * mc.half_width() + rel_slack * std::fabs(golden))
      << what << ": MC " << mc.value << " [" << mc.lo << ", " << mc.hi << "], golden " << golden;
}

// Variance interval from the std interval.
McInterval squared(const McInterval& s) { return {s.value * s.value, s.lo * s.lo, s.hi * s.hi}; }

TEST(McGolden, LsConventionalMeanAndVarianceAtFixedSpot) {
  const LsConventionalConfig cfg = ls_conventional_from_params(load_preset("ls-conventional"));
  const double sig = 0.05, bg = 0.003;
  ASSERT_EQ(golden::evaluate_point(cfg, sig, bg).detect, golden::Detect::Detectable);
  for (double u : {0.15, 0.5, 0.8}) {
    SCOPED_TRACE(u);
    const golden::RowModel row = golden::make_row_model(cfg, sig, bg);
    const double x0 = row.centre_pixel - 0.5 + u;
    const golden::PositionMoments g = golden::position_moments(row, x0);
    ASSERT_TRUE(g.exact);
    const McPointStats s = run(LsConventionalMc(cfg, SpotPlacement{u}), sig, bg, 4000);
    expect_agrees(s.p_detect, g.p_detect, 0, "p_detect");
    expect_agrees(s.bias, g.mean_px - x0, 0, "mean error (px)");
    expect_agrees(squared(s.std), g.var_px2, 0, "variance (px^2)");
    EXPECT_GT(s.std.value, 0.01);  // noise does move the estimate here
  }
}

// The golden accuracy averages the noise over spot positions. With a fixed rule of 16 positions it
// was not converged: at (0.12 V, 0.002 V) it gave 0.0675 px where Monte Carlo gives 0.0796 [0.0784,
// 0.0807] px (64: 0.0811, 256: 0.0794, 1024: 0.0792). The preset's adaptive rule
// (evaluation.subpixel_tolerance) refines the positions until the accuracy moves by < 2%; the
// comparison uses the preset as it is.
TEST(McGolden, LsConventionalAccuracyOverSpotPositions) {
  const LsConventionalConfig cfg = ls_conventional_from_params(load_preset("ls-conventional"));
  ASSERT_GT(cfg.grid.subpixel_tolerance, 0.0);
  for (auto [sig, bg] : {std::pair{0.05, 0.003}, std::pair{0.4, 0.02}, std::pair{0.12, 0.002}}) {
    SCOPED_TRACE(sig);
    const golden::OperatingPoint g = golden::evaluate_point(cfg, sig, bg);
    ASSERT_EQ(g.detect, golden::Detect::Detectable);
    EXPECT_GT(g.subpixel_positions, cfg.grid.subpixel_points);  // the 16-position rule was not enough here
    const McPointStats s = run(LsConventionalMc(cfg), sig, bg, 6000);
    expect_agrees(s.rms, g.accuracy_px, 0.0, "accuracy (px)");
  }
}

// The detection edge: at the thesis's point (0.01 V over 0.001 V) the noise-free peak sits exactly
// on the threshold, so noise decides each frame. Golden classes it detectable (rounding-tolerant
// threshold) with P(detect) strictly between 0 and 1 and the accuracy given detection.
TEST(McGolden, LsConventionalDetectionEdge) {
  const LsConventionalConfig cfg = ls_conventional_from_params(load_preset("ls-conventional"));
  const golden::OperatingPoint g = golden::evaluate_point(cfg, 0.01, 0.001);
  ASSERT_EQ(g.detect, golden::Detect::Detectable);
  const McPointStats s = run(LsConventionalMc(cfg), 0.01, 0.001, 3000);
  EXPECT_GT(s.p_detect.value, 0.05);
  EXPECT_LT(s.p_detect.value, 0.95);
  expect_agrees(s.rms, g.accuracy_px, 0.0, "accuracy at the edge (px)");
}

TEST(McGolden, TofLockinMeanAndVariance) {
  TofLockinConfig cfg = tof_lockin_from_params(load_preset("tof-lockin"));
  const double is = 3e-10, ib = 1e-10;
  const golden::LockinPoint g = golden::evaluate_point(cfg, is, ib, cfg.eval.distance_m, cfg.eval.frames_averaged);
  ASSERT_EQ(g.detect, golden::LockinDetect::Detectable);
  const McPointStats s = run(TofLockinMc(cfg), is, ib, 3000);
  EXPECT_EQ(s.detected, s.trials);
  expect_agrees(s.bias, g.bias_m, 0, "bias (m)");
  const double var = g.std_m * g.std_m / static_cast<double>(cfg.eval.frames_averaged);
  expect_agrees(squared(s.std), var, 0.10, "variance (m^2)");
  expect_agrees(s.rms, g.accuracy_m, 0.05, "accuracy (m)");
}

TEST(McGolden, TofSpadMeanAndVariance) {
  TofSpadConfig cfg = tof_spad_from_params(load_preset("tof-spad"));
  cfg.histogram.integration_time_s = 5e-3;  // keeps the test short; the model is the same
  const double sig = 4e4, bg = 2e5;
  const golden::spad::SpadModel model(cfg);
  const golden::spad::PointResult g = model.evaluate(sig, bg, cfg.evaluation.distance_m);
  ASSERT_EQ(g.detect, "detectable");
  ASSERT_TRUE(g.moments.defined);
  // The golden histogram bounds afterpulses but does not model them: off for the comparison.
  const McPointStats s = run(TofSpadMc(cfg, false), sig, bg, 500);
  EXPECT_EQ(s.detected, s.trials);
  expect_agrees(s.bias, g.bias_m, 0, "bias (m)");
  expect_agrees(squared(s.std), g.std_m * g.std_m, 0.10, "variance (m^2)");
}

// A chip with a fixed pattern (every trial another chip: TofSpadMc): the dark count rates spread
// by 3e5 counts/s rms (clipped at none, as the kernels draw them) around 100 counts/s under 1e5
// counts/s of background. Golden's accuracy is the rms over the chip's pixels (SpadModel::evaluate:
// Gauss-Hermite over the draw, the sharing columns at the draws' mean: a clipped spread raises
// the mean rate); it must lie within the stated test of the MC's, and the chip without the spread
// (what golden gave before) must not.
TEST(McGolden, TofSpadDarkCountSpreadOverTheChip) {
  TofSpadConfig cfg = tof_spad_from_params(load_preset("tof-spad"));
  cfg.histogram.integration_time_s = 5e-3;
  cfg.tdc.inl_rms_lsb = cfg.tdc.dnl_rms_lsb = 0;  // the noise, not the TDC's bow, sets the accuracy
  cfg.fixed_pattern.dsnu_rms = 3e5;
  const double sig = 3e4, bg = 1e5;
  const golden::spad::SpadModel model(cfg);
  const golden::spad::PointResult g = model.evaluate(sig, bg, cfg.evaluation.distance_m);
  TofSpadConfig uniform = cfg;
  uniform.fixed_pattern.dsnu_rms = 0;
  const golden::spad::PointResult plain = golden::spad::SpadModel(uniform).evaluate(sig, bg, cfg.evaluation.distance_m);
  ASSERT_EQ(g.detect, "detectable");
  const McPointStats s = run(TofSpadMc(cfg, false), sig, bg, 1000);
  expect_agrees(s.rms, g.accuracy_m, 0.0, "accuracy over the chip (m)");
  EXPECT_GT(std::fabs(s.rms.value - plain.accuracy_m), 2 * s.rms.half_width());
}

TEST(McGolden, LsDemodulationAccuracy) {
  const LsDemodulationConfig cfg = ls_demodulation_from_params(load_preset("ls-demodulation"));
  const double sig = cfg.grid.signal_min_A * 30, bg = cfg.grid.background_min_A * 10;
  const golden::DemodPoint g = golden::evaluate_demod_point(cfg, sig, bg);
  ASSERT_EQ(g.detect, golden::DemodDetect::Detectable);
  const McPointStats s = run(LsDemodulationMc(cfg), sig, bg, 600);
  expect_agrees(s.rms, g.accuracy.accuracy_px, 0.05, "accuracy (px)");
}

}  // namespace
}  // namespace rangesim::app::mc
