// ls-demodulation's non-idealities on the kernel's inputs (systemc/ls_demodulation/nonideal_stimulus.h):
// each comparator's fixed offset enters the decision exactly, and the pattern is the chip's, the
// same in every frame.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "golden/ls_demodulation/evaluation.h"
#include "systemc/ls_demodulation/montecarlo.h"
#include "systemc/ls_demodulation/nonideal_stimulus.h"
#include "systemc/ls_demodulation/sensor_kernel.h"
#include "tests/systemc/ls_demodulation/demod_test_helpers.h"

namespace rangesim::systemc {
namespace {

TEST(DemodNonideal, ComparatorOffsetEntersEveryDecisionOfItsPixel) {
  LsDemodulationConfig c = test::small_config(3, 16);
  c.fixed_pattern.comparator_offset_rms_V = 5e-3;  // half the 10 mV threshold: flips the edge pixels
  const DemodStimulusSource spot = test::spot_source(c, 1.11e-10, 1e-10, 7.3);
  const DemodStimulusSource chip = [&](std::uint64_t f, DemodStimulus& s) {
    spot(f, s);
    apply_demod_fixed_pattern(c, s);
  };
  DemodKernelOptions o;
  o.noise = DemodNoiseSwitches::none();
  o.keep_analogue = true;
  const DemodRunResult with = run_demod_kernel(c, o, chip, 2);
  DemodStimulus s;
  chip(0, s);
  ASSERT_EQ(s.comparator_offset_V.size(), 48u);
  int flipped = 0;
  for (const DemodFrameResult& f : with.frames)
    for (int r = 0; r < 3; ++r)
      for (int col = 0; col < 16; ++col) {
        const std::size_t i = static_cast<std::size_t>(r) * 16 + col;
        const double d = f.diff_V[i];  // one decision per frame in the preset
        EXPECT_EQ(f.activations[static_cast<std::size_t>(r)].test(col),
                  d + s.comparator_offset_V[i] >= c.comparator.threshold_V)
            << "frame " << f.frame << " row " << r << " column " << col;
        flipped += (d >= c.comparator.threshold_V) != (d + s.comparator_offset_V[i] >= c.comparator.threshold_V);
      }
  EXPECT_GT(flipped, 0);  // the offsets matter at this spot
  // The same chip in every frame.
  EXPECT_EQ(with.frames[0].rows, with.frames[1].rows);
}

TEST(DemodNonideal, FixedPatternHasItsRmsAndIsTheSameEveryFrame) {
  LsDemodulationConfig c = test::preset_config();
  c.fixed_pattern.prnu_fraction = 0.02;
  c.fixed_pattern.comparator_offset_rms_V = 1e-3;
  DemodStimulus a, b;
  for (DemodStimulus* s : {&a, &b}) {
    s->beam_A.assign(static_cast<std::size_t>(c.pixel.rows) * c.pixel.columns, 1e-9);
    s->background_A.assign(s->beam_A.size(), 0.0);
    apply_demod_fixed_pattern(c, *s);
  }
  EXPECT_EQ(a.beam_A, b.beam_A);
  EXPECT_EQ(a.comparator_offset_V, b.comparator_offset_V);
  double g2 = 0, o2 = 0;
  for (std::size_t i = 0; i < a.beam_A.size(); ++i)
    g2 += std::pow(a.beam_A[i] / 1e-9 - 1, 2), o2 += a.comparator_offset_V[i] * a.comparator_offset_V[i];
  const double n = static_cast<double>(a.beam_A.size());  // 13200 pixels: rms to 0.6 %
  EXPECT_NEAR(std::sqrt(g2 / n), 0.02, 0.02 * 0.03);
  EXPECT_NEAR(std::sqrt(o2 / n), 1e-3, 1e-3 * 0.03);
  // Another chip, another pattern.
  c.fixed_pattern.seed = 2;
  apply_demod_fixed_pattern(c, b);
  EXPECT_NE(a.comparator_offset_V, b.comparator_offset_V);
}

// Golden's accuracy with the comparators' fixed offsets (golden/ls_demodulation/fixed_pattern.h)
// against the Monte Carlo of the kernel, every trial a row of another chip: exact for one frame,
// the averaging floor (first order) for 16.
TEST(DemodNonideal, ComparatorOffsetsAgainstMonteCarloAndTheirFloor) {
  LsDemodulationConfig c = test::preset_config();
  c.fixed_pattern.comparator_offset_rms_V = 2e-3;
  const double s = 1.11e-10, b = 1e-10;
  for (int frames : {1, 16}) {
    c.grid.frames_averaged = frames;
    LsDemodulationConfig off = c;
    off.fixed_pattern.comparator_offset_rms_V = 0;
    const golden::DemodPoint g = golden::evaluate_demod_point(c, s, b);
    const golden::DemodPoint g_off = golden::evaluate_demod_point(off, s, b);
    ASSERT_EQ(g.detect, golden::DemodDetect::Detectable);
    const mc::LsDemodulationMc model(c);
    const auto runner = model.point(s, b, 99);
    const int n = frames == 1 ? 20000 : 400;
    std::vector<double> sq;
    for (int t = 0; t < n; ++t) {
      const mc::McTrial tr = runner->trial(t);
      if (tr.detected) sq.push_back(tr.error * tr.error);
    }
    ASSERT_GT(sq.size(), n * 0.99);
    double m2 = 0, m4 = 0;
    for (double e : sq) m2 += e;
    m2 /= static_cast<double>(sq.size());
    for (double e : sq) m4 += (e - m2) * (e - m2);
    // Standard error of the mean squared error from the sample itself: the errors have heavy
    // tails (a far pixel whose offset lets the background through moves an edge by many pixels).
    const double se = std::sqrt(m4 / static_cast<double>(sq.size()) / static_cast<double>(sq.size()));
    const double mc_px = std::sqrt(m2), g2 = g.accuracy.accuracy_px * g.accuracy.accuracy_px;
    EXPECT_NEAR(m2, g2, 4 * se) << frames << " frames: MC " << mc_px << " px, golden " << g.accuracy.accuracy_px
                                << " px (mean square +- " << se << "), without offsets " << g_off.accuracy.accuracy_px
                                << " px";
    if (frames == 16)
      EXPECT_GT(mc_px, 1.5 * g_off.accuracy.accuracy_px)
          << "the floor: MC " << mc_px << " golden " << g.accuracy.accuracy_px << " without "
          << g_off.accuracy.accuracy_px;
  }
}

// Mean squared error of the detected trials without an outlier and its standard error, from the
// sample itself (the errors have heavy tails).
struct MeanSquare {
  double m2 = 0, se = 0;
  long long outliers = 0;
};
MeanSquare clean_mean_square(const mc::McModel& model, double s, double b, int n) {
  const auto runner = model.point(s, b, 7);
  std::vector<double> sq;
  MeanSquare r;
  for (int t = 0; t < n; ++t) {
    const mc::McTrial tr = runner->trial(t);
    if (tr.outlier) ++r.outliers;
    if (tr.detected && !tr.outlier) sq.push_back(tr.error * tr.error);
  }
  const double k = static_cast<double>(sq.size());
  for (double e : sq) r.m2 += e / k;
  double m4 = 0;
  for (double e : sq) m4 += (e - r.m2) * (e - r.m2);
  r.se = std::sqrt(m4 / k / k);
  return r;
}

// Golden's PRNU (golden/ls_demodulation/decision.h, fixed_pattern.h) against the Monte Carlo of the
// kernel, every trial a row of another chip, one frame (the preset's): 20 % PRNU moves the spot's
// edge pixels and raises the accuracy from 0.241 to 0.288 px at the weakest signal of the issue's
// grid. 20000 trials: the mean square's 95 % half-width is about 2.5 %, so golden 3 % off in rms
// (6 % in mean square) fails, and the golden without the pattern fails by many half-widths.
TEST(DemodNonideal, PrnuAgainstMonteCarlo) {
  LsDemodulationConfig c = test::preset_config();
  c.fixed_pattern.prnu_fraction = 0.2;
  const double s = 1.37933e-11, b = 7.4e-13;
  LsDemodulationConfig off = c;
  off.fixed_pattern.prnu_fraction = 0;
  const golden::DemodPoint g = golden::evaluate_demod_point(c, s, b);
  const golden::DemodPoint g_off = golden::evaluate_demod_point(off, s, b);
  ASSERT_EQ(g.detect, golden::DemodDetect::Detectable);
  const MeanSquare m = clean_mean_square(mc::LsDemodulationMc(c), s, b, 20000);
  const double g2 = g.accuracy.accuracy_clean_px * g.accuracy.accuracy_clean_px;
  // Within 3.92 standard errors (2 half-widths of its 95 % interval).
  EXPECT_NEAR(m.m2, g2, 3.92 * m.se) << "MC " << std::sqrt(m.m2) << " px, golden " << g.accuracy.accuracy_clean_px;
  for (double f : {0.97, 1.03})  // the power: golden 3 % off would fail
    EXPECT_GT(std::fabs(m.m2 - f * f * g2), 3.92 * m.se) << f;
  const double g_off2 = g_off.accuracy.accuracy_px * g_off.accuracy.accuracy_px;
  EXPECT_GT(std::fabs(m.m2 - g_off2), 10 * m.se) << "without PRNU golden gives " << g_off.accuracy.accuracy_px;
}

// DSNU: the LPF removes a pixel's constant current, so a dark-current spread moves D only through
// the mirror mismatch residue and the log stage, and adds shot noise. At 10 pA rms (10^4 times the
// 1 fA dark current, 13 times the background here) the accuracy moves by less than 1 %, in golden
// and in the Monte Carlo alike (20000 trials, power as above). Where the spread is far above the
// background (100 pA here) the pixels' shot-noise variances spread so much that their activation
// tails are heavier than golden's Gaussian form of the pattern: the Monte Carlo's accuracy is then
// 1.8 % above golden's (docs/model-limits.md).
TEST(DemodNonideal, DsnuAgainstMonteCarlo) {
  LsDemodulationConfig c = test::preset_config();
  c.fixed_pattern.dsnu_rms = 1e-11;
  const double s = 1.37933e-11, b = 7.4e-13;
  LsDemodulationConfig off = c;
  off.fixed_pattern.dsnu_rms = 0;
  const golden::DemodPoint g = golden::evaluate_demod_point(c, s, b);
  const golden::DemodPoint g_off = golden::evaluate_demod_point(off, s, b);
  ASSERT_EQ(g.detect, golden::DemodDetect::Detectable);
  EXPECT_NE(g.accuracy.accuracy_clean_px, g_off.accuracy.accuracy_px);  // the closed form is in
  EXPECT_NEAR(g.accuracy.accuracy_clean_px, g_off.accuracy.accuracy_px, 0.01 * g_off.accuracy.accuracy_px);
  const MeanSquare m = clean_mean_square(mc::LsDemodulationMc(c), s, b, 20000);
  const double g2 = g.accuracy.accuracy_clean_px * g.accuracy.accuracy_clean_px;
  EXPECT_NEAR(m.m2, g2, 3.92 * m.se) << "MC " << std::sqrt(m.m2) << " px, golden " << g.accuracy.accuracy_clean_px;
  for (double f : {0.97, 1.03}) EXPECT_GT(std::fabs(m.m2 - f * f * g2), 3.92 * m.se) << f;
  EXPECT_EQ(m.outliers, 0);
}

}  // namespace
}  // namespace rangesim::systemc
