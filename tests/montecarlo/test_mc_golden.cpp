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
#include <cstdio>

#include "app/montecarlo/mc_stats.h"
#include "core/physics.h"
#include "core/preset.h"
#include "mc_point_run.h"
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

// golden within 2 CI half-widths of the MC value, plus a relative slack for approximations.
void expect_agrees(const McInterval& mc, double golden, double rel_slack, const char* what) {
  EXPECT_LE(std::fabs(mc.value - golden), 2 * mc.half_width() + rel_slack * std::fabs(golden))
      << what << ": MC " << mc.value << " [" << mc.lo << ", " << mc.hi << "], golden " << golden;
}

// The power of a comparison: golden off by `change` (3 % unless stated) either way would fail it
// (the companion of each statistical test, as the house rules ask).
void expect_catches_three_percent(const McInterval& mc, double golden, const char* what, double change = 0.03) {
  for (double f : {1 - change, 1 + change})
    EXPECT_GT(std::fabs(mc.value - f * golden), 2 * mc.half_width())
        << what << ": a golden " << f << " x " << golden << " would pass against MC " << mc.value << " [" << mc.lo
        << ", " << mc.hi << "]";
}

// A probability: golden within 2 half-widths of the Wilson interval on its side.
void expect_probability_agrees(const McInterval& mc, double golden, const char* what) {
  const double side = golden >= mc.value ? mc.hi - mc.value : mc.value - mc.lo;
  EXPECT_LE(std::fabs(golden - mc.value), 2 * side + 1e-12)
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
    const McPointStats s = run_mc_point(LsConventionalMc(cfg, SpotPlacement{u}), sig, bg, 4000);
    expect_agrees(s.p_detect, g.p_detect, 0, "p_detect");
    expect_agrees(s.bias, g.mean_px - x0, 0, "mean error (px)");
    expect_agrees(squared(s.std), g.var_px2, 0, "variance (px^2)");
    EXPECT_GT(s.std.value, 0.01);  // noise does move the estimate here
  }
}

// The golden accuracy averages the noise over spot positions. With a fixed rule of 16 positions it
// was not converged: at (0.12 V, 0.002 V) it gave 0.0675 px where Monte Carlo gives 0.0796 [0.0784,
// 0.0807] px (64: 0.0811, 256: 0.0794, 1024: 0.0792). The preset's adaptive rule
// (evaluation.subpixel_tolerance: Gauss-Kronrod between the noise-free breakpoints to an estimated
// 0.1 %) is converged; the comparison uses the preset as it is.
TEST(McGolden, LsConventionalAccuracyOverSpotPositions) {
  const LsConventionalConfig cfg = ls_conventional_from_params(load_preset("ls-conventional"));
  ASSERT_GT(cfg.grid.subpixel_tolerance, 0.0);
  for (auto [sig, bg] : {std::pair{0.05, 0.003}, std::pair{0.4, 0.02}, std::pair{0.12, 0.002}}) {
    SCOPED_TRACE(sig);
    const golden::OperatingPoint g = golden::evaluate_point(cfg, sig, bg);
    ASSERT_EQ(g.detect, golden::Detect::Detectable);
    EXPECT_TRUE(g.subpixel_converged);
    EXPECT_LE(g.subpixel_error_estimate, cfg.grid.subpixel_tolerance);
    const McPointStats s = run_mc_point(LsConventionalMc(cfg), sig, bg, 6000);
    expect_agrees(s.rms, g.accuracy_px, 0.0, "accuracy (px)");
  }
}

// The detection edge: at the thesis's point (0.01 V over 0.001 V) the noise-free peak sits exactly
// on the threshold, so noise decides each frame. Golden classes it detectable (rounding-tolerant
// threshold) with P(detect) strictly between 0 and 1 (exact: the mean over spot positions) and the
// accuracy given detection.
TEST(McGolden, LsConventionalDetectionEdge) {
  const LsConventionalConfig cfg = ls_conventional_from_params(load_preset("ls-conventional"));
  const golden::OperatingPoint g = golden::evaluate_point(cfg, 0.01, 0.001);
  ASSERT_EQ(g.detect, golden::Detect::Detectable);
  const McPointStats s = run_mc_point(LsConventionalMc(cfg), 0.01, 0.001, 3000);
  EXPECT_GT(s.p_detect.value, 0.05);
  EXPECT_LT(s.p_detect.value, 0.95);
  expect_probability_agrees(s.p_detect, g.p_detect, "P(detect) at the edge");
  expect_agrees(s.rms, g.accuracy_px, 0.0, "accuracy at the edge (px)");
}

// Points the golden model missed before (evaluate ls-conventional --trials 1000 on the preset's
// grid), each against 100000 trials (95% CI half-width 0.3-0.6 %: golden 3 % off fails):
//  - 0.01013 V over 0.001 V, just above the edge: the noise-free readout detects at some spot
//    positions, noise decides at all of them (P(detect) 0.43); golden gave 2.2 mm, MC 4.5 mm. The
//    average over positions is now weighted by P(detect) everywhere;
//  - 0.131 V over 0.001995 V and 1.5 V over 0.002512 V: the average over spot positions (then
//    "tripled until it moves < 2 %") was 9 % and 6 % off; now adaptive Gauss-Kronrod to 0.1 %.
TEST(McGolden, LsConventionalFormerMisses) {
  const LsConventionalConfig cfg = ls_conventional_from_params(load_preset("ls-conventional"));
  int index = 0;
  // Points of the preset's grid (20 per decade from 0.001 V; signal to 1.5 V in 60 steps).
  const double step = std::pow(1500.0, 1.0 / 60);
  for (auto [sig, bg] :
       {std::pair{1e-3 * std::pow(step, 19), 1e-3}, std::pair{1e-3 * std::pow(step, 40), 1e-3 * std::pow(10.0, 0.3)},
        std::pair{1.5, 1e-3 * std::pow(10.0, 0.4)}}) {
    SCOPED_TRACE(sig);
    const golden::OperatingPoint g = golden::evaluate_point(cfg, sig, bg);
    ASSERT_EQ(g.detect, golden::Detect::Detectable);
    const McPointStats s = run_mc_point(LsConventionalMc(cfg), sig, bg, 100000, static_cast<std::uint64_t>(++index));
    expect_probability_agrees(s.p_detect, g.p_detect, "P(detect)");
    expect_agrees(s.rms, g.accuracy_px, 0.0, "accuracy (px)");
    expect_catches_three_percent(s.rms, g.accuracy_px, "accuracy (px)");
  }
}

// Outliers at 1 V background: a background pixel 4.9 sigma of shot noise above its mean crosses the
// tracking threshold in 2e-4 of the frames and moves an edge by up to ~190 px, so golden's total
// accuracy (14.9 mm at 0.027 V) is dominated by frames a few thousand trials rarely see (MC 4.4 mm
// at 1000 trials: the old failure). Golden and the MC both split them off: the accuracy of the
// frames without an outlier and P(outlier) agree at any trial count; the total needs trials >>
// 1 / P(outlier) (McGoldenHeavy). 20000 trials: clean accuracy's CI half-width about 1 %.
TEST(McGolden, LsConventionalOutliersSplitOff) {
  const LsConventionalConfig cfg = ls_conventional_from_params(load_preset("ls-conventional"));
  int index = 10;
  // Points of the grid --signal 0.01:1.5:6.
  for (double sig : {0.01 * std::pow(150.0, 0.2), 0.01 * std::pow(150.0, 0.8)}) {
    SCOPED_TRACE(sig);
    const golden::OperatingPoint g = golden::evaluate_point(cfg, sig, 1.0);
    ASSERT_EQ(g.detect, golden::Detect::Detectable);
    EXPECT_GT(g.p_outlier, 1e-4);
    EXPECT_GT(g.accuracy_px, 3 * g.accuracy_clean_px);  // the outliers dominate the total
    const McPointStats s = run_mc_point(LsConventionalMc(cfg), sig, 1.0, 20000, static_cast<std::uint64_t>(++index));
    expect_probability_agrees(s.p_outlier, g.p_outlier, "P(outlier)");
    expect_probability_agrees(s.p_detect, g.p_detect, "P(detect)");
    expect_agrees(s.rms_clean, g.accuracy_clean_px, 0.0, "accuracy without outliers (px)");
    expect_catches_three_percent(s.rms_clean, g.accuracy_clean_px, "accuracy without outliers (px)");
  }
}

TEST(McGolden, TofLockinMeanAndVariance) {
  TofLockinConfig cfg = tof_lockin_from_params(load_preset("tof-lockin"));
  const double is = 3e-10, ib = 1e-10;
  const golden::LockinPoint g = golden::evaluate_point(cfg, is, ib, cfg.eval.distance_m, cfg.eval.frames_averaged);
  ASSERT_EQ(g.detect, golden::LockinDetect::Detectable);
  const McPointStats s = run_mc_point(TofLockinMc(cfg), is, ib, 3000);
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
  const McPointStats s = run_mc_point(TofSpadMc(cfg, false), sig, bg, 500);
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
  const McPointStats s = run_mc_point(TofSpadMc(cfg, false), sig, bg, 1000);
  expect_agrees(s.rms, g.accuracy_m, 0.0, "accuracy over the chip (m)");
  EXPECT_GT(std::fabs(s.rms.value - plain.accuracy_m), 2 * s.rms.half_width());
}

// The SPAD's timing jitter in the physical order (golden/tof_spad/timing_jitter.h): each SPAD
// fires on its first photon by true arrival, the avalanche's timestamp is jittered, the TDC takes
// the first recorded one. At 1e6 counts/s of signal and 10 of background (a strong echo, 0.025
// photons per SPAD and pulse; the accuracy is the TDC bow's bias) golden's accuracy lies within
// the stated test of the MC's, all noise on as `evaluate --trials` runs it. Golden in the former
// order (the first *jittered* photon fires: the jitter folded into the pulse's width) was 1.8 %
// low here and must fail. 400 trials: the half-width is about 0.4 % (the accuracy is mostly bias),
// so the test fails a golden more than about 0.8 % off; the companion checks 3 %.
TEST(McGolden, TofSpadJitterAfterTheFirstPhoton) {
  const TofSpadConfig cfg = tof_spad_from_params(load_preset("tof-spad"));
  const double sig = 1e6, bg = 10, d = cfg.evaluation.distance_m;
  const golden::spad::PointResult g = golden::spad::SpadModel(cfg).evaluate(sig, bg, d);
  ASSERT_EQ(g.detect, "detectable");
  TofSpadConfig folded = cfg;  // the former order: arrivals with the whole IRF, no jitter after
  folded.laser.pulse_fwhm_s = golden::spad::irf_sigma_s(cfg) / cfg.laser.sigma_per_fwhm;
  folded.spad.jitter_sigma_s = 0;
  const golden::spad::PointResult before = golden::spad::SpadModel(folded).evaluate(sig, bg, d);
  const McPointStats s = run_mc_point(TofSpadMc(cfg), sig, bg, 400, 5);
  std::printf("accuracy: MC %.4f [%.4f, %.4f] mm, golden %.4f mm, the former order %.4f mm\n", s.rms.value * 1e3,
              s.rms.lo * 1e3, s.rms.hi * 1e3, g.accuracy_m * 1e3, before.accuracy_m * 1e3);
  EXPECT_EQ(s.detected, s.trials);
  expect_agrees(s.rms, g.accuracy_m, 0.0, "accuracy (m)");
  EXPECT_GT(std::fabs(s.rms.value - before.accuracy_m), 2 * s.rms.half_width())
      << "the former order " << before.accuracy_m << " passes against MC " << s.rms.value;
  expect_catches_three_percent(s.rms, g.accuracy_m, "accuracy (m)");
}

TEST(McGolden, LsDemodulationAccuracy) {
  const LsDemodulationConfig cfg = ls_demodulation_from_params(load_preset("ls-demodulation"));
  const double sig = cfg.grid.signal_min_A * 30, bg = cfg.grid.background_min_A * 10;
  const golden::DemodPoint g = golden::evaluate_demod_point(cfg, sig, bg);
  ASSERT_EQ(g.detect, golden::DemodDetect::Detectable);
  const McPointStats s = run_mc_point(LsDemodulationMc(cfg), sig, bg, 600);
  expect_agrees(s.rms, g.accuracy.accuracy_px, 0.05, "accuracy (px)");
}

// ls-demodulation where background pixels may fire (0.265 nA background: its shot noise lets a
// background-only pixel cross V_cmp in 6e-3 of the frames, an edge moved by up to the row's width):
// as for ls-conventional, golden and the MC split those trials off. 20000 trials: the clean
// accuracy's CI half-width is about 3 % (broad errors at this background), so golden 10 % off
// fails here (the fast subset); McGoldenHeavy.LsDemodulationOutliersSplitOff runs 100000 trials
// and catches 3 %.
TEST(McGolden, LsDemodulationOutliersSplitOff) {
  const LsDemodulationConfig cfg = ls_demodulation_from_params(load_preset("ls-demodulation"));
  const double sig = 2.86601e-11,
               bg = 2.65302e-10;  // a point of --signal 7.4e-13:1.11e-9:9 --background 7.4e-13:1e-6:13
  const golden::DemodPoint g = golden::evaluate_demod_point(cfg, sig, bg);
  ASSERT_EQ(g.detect, golden::DemodDetect::Detectable);
  EXPECT_GT(g.accuracy.p_outlier, 1e-3);
  EXPECT_GT(g.accuracy.accuracy_px, 3 * g.accuracy.accuracy_clean_px);
  const McPointStats s = run_mc_point(LsDemodulationMc(cfg), sig, bg, 20000, 3);
  expect_probability_agrees(s.p_outlier, g.accuracy.p_outlier, "P(outlier)");
  expect_probability_agrees(s.p_detect, g.accuracy.p_detect, "P(detect)");
  expect_agrees(s.rms_clean, g.accuracy.accuracy_clean_px, 0.0, "accuracy without outliers (px)");
  expect_catches_three_percent(s.rms_clean, g.accuracy.accuracy_clean_px, "accuracy without outliers (px)", 0.10);
}

}  // namespace
}  // namespace rangesim::app::mc
