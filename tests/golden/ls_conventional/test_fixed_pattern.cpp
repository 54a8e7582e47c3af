// ls-conventional golden with the chip's fixed pattern (golden/common/fixed_pattern_activation.h):
// the comparator offset is static noise by variance addition, PRNU and DSNU are averaged by a
// trapezoid rule that agrees with an independent fine integral, and PRNU x background against the
// tracking threshold's fixed margin sets false activations at high background.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <utility>

#include "golden/common/activation_cdf.h"
#include "golden/common/fixed_pattern_activation.h"
#include "golden/common/pixel.h"
#include "golden/common/position_noise.h"
#include "golden/common/quantiser.h"
#include "golden/common/row_model.h"
#include "golden/ls_conventional/detect.h"
#include "test_helpers.h"

namespace rangesim::golden {
namespace {

// E over z of activation_probability at lambda(z): midpoint sums of 4001 points each side of the
// clip's kink (z = -1/p or -I_d/d) over +-9, the weights the normal density, renormalised.
double fine_average(const LsConventionalConfig& cfg, double photo_e, double t, double thr_e, double sig_e) {
  const double p = cfg.fixed_pattern.prnu_fraction, d = cfg.fixed_pattern.dsnu_rms;
  const PixelConfig& px = cfg.pixel;
  const double per_A = px.integration_time_s / px.pd_capacitance_F * electrons_per_volt(px) * t;
  const double kink = std::clamp(p > 0 ? -1 / p : -px.dark_current_A / d, -9.0, 9.0);
  double sum = 0, wsum = 0;
  const int n = 4001;
  for (auto [a, b] : {std::pair{-9.0, kink}, std::pair{kink, 9.0}})
    for (int i = 0; i < n; ++i) {
      const double z = a + (b - a) * (i + 0.5) / n, w = (b - a) / n * std::exp(-0.5 * z * z);
      // One normal drives whichever of PRNU or DSNU is on (the tests turn on one at a time).
      const double photo = std::max(0.0, 1 + p * z) * photo_e;
      const double dark = std::max(0.0, px.dark_current_A + d * z) * per_A;
      sum += w * activation_probability(photo + dark, thr_e, sig_e).p;
      wsum += w;
    }
  return sum / wsum;
}

TEST(GoldenFixedPattern, ComparatorOffsetIsStaticNoiseByVarianceAddition) {
  LsConventionalConfig with = test::preset_config(), wider = with;
  with.fixed_pattern.comparator_offset_rms_V = 0.002;
  wider.pixel.read_noise_V = std::hypot(wider.pixel.read_noise_V, 0.002 / wider.pixel.source_follower_gain);
  EXPECT_DOUBLE_EQ(static_noise_V(with), static_noise_V(wider.pixel));
  const RowModel a = make_row_model(with, 0.05, 0.003), b = make_row_model(wider, 0.05, 0.003);
  const double x0 = a.centre_pixel + 0.2;
  const PositionMoments ma = position_moments(a, x0), mb = position_moments(b, x0);
  EXPECT_NEAR(ma.var_px2, mb.var_px2, 1e-12 * mb.var_px2);
  EXPECT_NEAR(ma.mean_px, mb.mean_px, 1e-12);
  // ... and it matters: 2 mV against the 10 mV margin more than doubles the variance here.
  const PositionMoments none = position_moments(make_row_model(test::preset_config(), 0.05, 0.003), x0);
  EXPECT_GT(ma.var_px2, 2 * none.var_px2);
  EXPECT_GT(pixel_false_activation_probability(with, 0.3),
            100 * pixel_false_activation_probability(test::preset_config(), 0.3));
}

TEST(GoldenFixedPattern, PrnuAndDsnuAverageAgreesWithAFineIntegral) {
  LsConventionalConfig prnu = test::preset_config(), dsnu = prnu;
  prnu.fixed_pattern.prnu_fraction = 0.02;
  dsnu.fixed_pattern.dsnu_rms = 2e-12;  // 2.5 mV of dark swing rms; half the pixels clip at zero current
  const double e_per_V = electrons_per_volt(prnu.pixel), A = prnu.pixel.source_follower_gain;
  int checked = 0;
  for (const LsConventionalConfig* cfg : {&prnu, &dsnu})
    for (double bg : {0.003, 0.15})
      for (double t : {0.25, 1.0}) {
        const double sig_e = static_noise_V(*cfg) * e_per_V;
        const double thr_e = comparator_threshold_V(*cfg, bg) / A * e_per_V;
        for (double rel : {-0.05, -0.02, 0.0, 0.01, 0.03, 0.1}) {
          const double photo_e = thr_e * (1 + rel) - dark_voltage_V(cfg->pixel) * e_per_V * t;
          ActivationCache cache;
          const double got = fixed_pattern_activation(*cfg, cache, photo_e, t, thr_e, sig_e).p;
          const double want = fine_average(*cfg, photo_e, t, thr_e, sig_e);
          // The midpoint reference's own error is ~2e-7 here (h^2 / 24 f''); before the rule was split
          // at the clip's kink it was 1e-3 off. The rule 4x finer moves it by < 1e-10: converged.
          EXPECT_NEAR(got, want, 1e-6) << "bg " << bg << " t " << t << " rel " << rel;
          ActivationCache fine_cache;
          EXPECT_NEAR(got, fixed_pattern_activation(*cfg, fine_cache, photo_e, t, thr_e, sig_e, 4).p, 1e-10);
          checked += want > 1e-6 && want < 1 - 1e-6;
        }
      }
  EXPECT_GT(checked, 8);  // the comparisons include pixels that the pattern leaves undecided
}

// The tracking threshold sits a fixed 10 mV above the background; a pixel gain p scales the
// background by 1 + p z, so at V_bg the spread p V_bg meets that margin: 2 % PRNU at 0.3 V is 6 mV
// rms, and a row of 375 pixels activates falsely in most frames (the chip's limit at 2 %).
TEST(GoldenFixedPattern, PrnuTimesBackgroundSetsFalseActivations) {
  LsConventionalConfig cfg = test::preset_config();
  const double clean = row_false_activation_probability(cfg, 0.3);
  EXPECT_LT(clean, 1e-6);
  cfg.fixed_pattern.prnu_fraction = 0.02;
  const double with = row_false_activation_probability(cfg, 0.3);
  EXPECT_GT(with, 0.5);
  EXPECT_EQ(classify(cfg, 0.5, 0.3), Detect::BackgroundActivation);
  EXPECT_EQ(classify(test::preset_config(), 0.5, 0.3), Detect::Detectable);
  // Estimate: the background pixel fires when p V_bg z + noise > 10 mV: Gaussian with the noise.
  const double e_per_V = electrons_per_volt(cfg.pixel);
  const double noise_V = std::sqrt(0.3 / e_per_V + std::pow(static_noise_V(cfg), 2) + std::pow(0.02 * 0.3, 2));
  const double estimate = 0.5 * std::erfc(0.01 / noise_V / std::sqrt(2.0));
  EXPECT_NEAR(pixel_false_activation_probability(cfg, 0.3), estimate, 0.1 * estimate);
}

}  // namespace
}  // namespace rangesim::golden
