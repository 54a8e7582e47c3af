// ls-demodulation's fixed pattern in golden's decision (golden/ls_demodulation/decision.h,
// fixed_pattern.h): PRNU and DSNU move D, whose mean and variance over the chip's draws golden takes
// at 5 x 3 Gauss-Hermite nodes. Checked against a fine quadrature of the same chain over the draws,
// which makes no polynomial assumption.
#include <gtest/gtest.h>

#include <cmath>

#include "golden/ls_demodulation/decision.h"
#include "golden/ls_demodulation/front_end.h"
#include "tests/golden/ls_demodulation/test_helpers_demod.h"

namespace rangesim::golden {
namespace {

// Mean and variance of D over z ~ N(0, 1) by the trapezoid rule on [-8, 8] (4001 nodes): D of the
// chip pixel with gain max(0, 1 + p z) (PRNU) or dark offset sigma_d z (DSNU), as the kernels apply them.
struct Moments {
  double mean = 0, var = 0;
};
Moments reference(const LsDemodulationConfig& cfg, double beam_A, double background_A, double prnu, double dsnu_A) {
  const int n = 4001;
  const double h = 16.0 / (n - 1);
  double w_sum = 0, m1 = 0, m2 = 0;
  for (int i = 0; i < n; ++i) {
    const double z = -8 + i * h, w = std::exp(-0.5 * z * z) * (i == 0 || i == n - 1 ? 0.5 : 1.0);
    const double G = std::max(0.0, 1 + prnu * z);
    const double bg = std::max(-cfg.noise.dark_current_A, background_A * G + dsnu_A * z);
    const double d = correlate_periodic(cfg, pixel_segments(cfg, beam_A * G, bg), cfg.correlator.cycles).diff_V;
    w_sum += w, m1 += w * d, m2 += w * d * d;
  }
  m1 /= w_sum;
  return {m1, m2 / w_sum - m1 * m1};
}

// Without a pattern nothing changes: the chip's mean is the nominal D and its part is the
// comparator offset alone.
TEST(DemodFixedPattern, NoPatternIsTheNominalPixel) {
  LsDemodulationConfig cfg = test::demod_cfg();
  cfg.fixed_pattern.comparator_offset_rms_V = 1e-3;
  const PixelDecision d = pixel_decision(cfg, 5e-11, 1e-10);
  EXPECT_EQ(d.mean_V, d.out.diff_V);
  EXPECT_DOUBLE_EQ(d.sigma_chip_V, 1e-3);
}

// PRNU on the beam and background (20 %, a large spread so that the log stage's curvature shows):
// the chip's mean and spread of D at a spot-edge pixel near the 10 mV threshold (the pixels whose
// decisions the pattern changes: 0.1 %) and on a strong background; at the peak of a strong spot
// the negative half-periods clip at the log stage's floor for part of the draws, a kink the
// polynomial rule follows to 3 % (that pixel is far above the threshold either way).
TEST(DemodFixedPattern, PrnuMomentsAgainstFineQuadrature) {
  LsDemodulationConfig cfg = test::demod_cfg();
  cfg.fixed_pattern.prnu_fraction = 0.2;
  struct Case {
    double beam, bg, sd_tol;
  };
  for (const Case& c : {Case{1.2e-11, 7.4e-13, 0.001}, Case{5e-11, 1e-7, 0.001}, Case{1.11e-9, 1e-10, 0.03}}) {
    SCOPED_TRACE(c.beam);
    const PixelDecision d = pixel_decision(cfg, c.beam, c.bg);
    const Moments ref = reference(cfg, c.beam, c.bg, 0.2, 0);
    EXPECT_NEAR(d.mean_V, ref.mean, 1e-3 * std::fabs(ref.mean));
    EXPECT_NEAR(d.sigma_chip_V, std::sqrt(ref.var), c.sd_tol * std::sqrt(ref.var));
    EXPECT_GT(d.sigma_chip_V, 0.1 * 0.2 * std::fabs(d.out.diff_V));  // the spread is there
    EXPECT_GT(d.sigma_independent_V, d.sigma_chip_V);
  }
}

// DSNU: a dark-current spread comparable to the background. The LPF removes a pixel's constant
// current, so D moves only through the mirror mismatch residue and the log stage: the spread is
// small, but golden's moments are those of the chain.
TEST(DemodFixedPattern, DsnuMomentsAgainstFineQuadrature) {
  LsDemodulationConfig cfg = test::demod_cfg();
  cfg.fixed_pattern.dsnu_rms = 1e-10;
  for (auto [beam, bg] : {std::pair{1.2e-11, 2.5e-10}, std::pair{1.11e-9, 5e-10}}) {
    SCOPED_TRACE(beam);
    const PixelDecision d = pixel_decision(cfg, beam, bg);
    const Moments ref = reference(cfg, beam, bg, 0, 1e-10);
    EXPECT_NEAR(d.mean_V, ref.mean, 1e-3 * std::fabs(ref.mean));
    EXPECT_NEAR(d.sigma_chip_V, std::sqrt(ref.var), 0.02 * std::sqrt(ref.var) + 1e-9);
  }
}

}  // namespace
}  // namespace rangesim::golden
