// tof-spad's fixed pattern on the kernels' inputs (systemc/tof_spad/nonideal_rates.h) and the
// temperature law of the dark count rate (core/nonideal.h).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "core/physics.h"
#include "core/preset.h"
#include "core/schemas.h"
#include "core/tof_spad/config.h"
#include "golden/tof_spad/point_model.h"
#include "systemc/tof_spad/nonideal_rates.h"
#include "systemc/tof_spad/sensor_kernel.h"

namespace rangesim::systemc::spad {
namespace {

TofSpadConfig preset_config() {
  return tof_spad_from_params(load_preset_file(std::string(RANGESIM_SOURCE_DIR) + "/presets/tof-spad.toml"));
}

TEST(SpadNonideal, PdeAndDarkCountSpreadOverTheArray) {
  TofSpadConfig cfg = preset_config();
  cfg.fixed_pattern.prnu_fraction = 0.03;
  cfg.fixed_pattern.dsnu_rms = 20.0;  // Hz around the preset's 100 Hz: the clamp at 0 is 5 sigma away
  double g2 = 0, d2 = 0, n = 0;
  for (int r = 0; r < cfg.array.rows; ++r)
    for (int c = 0; c < cfg.array.columns; ++c) {
      const PixelRates p = with_fixed_pattern(cfg, 1, PixelRates{1e6, 2e6, 1e-8}, r, c);
      EXPECT_DOUBLE_EQ(p.background_Hz / p.signal_Hz, 2.0);  // one PDE for both
      EXPECT_GE(cfg.spad.dark_count_rate_Hz + p.dark_extra_Hz, 0.0);
      g2 += std::pow(p.signal_Hz / 1e6 - 1, 2), d2 += p.dark_extra_Hz * p.dark_extra_Hz, ++n;
    }
  // 16384 pixels: the rms to 0.6 % (1 sigma).
  EXPECT_NEAR(std::sqrt(g2 / n), 0.03, 0.03 * 0.03);
  EXPECT_NEAR(std::sqrt(d2 / n), 20.0, 20.0 * 0.03);
  // The same chip gives the same pixel; another chip another one.
  const PixelRates a = with_fixed_pattern(cfg, 1, PixelRates{1e6, 0, 0}, 5, 7);
  EXPECT_EQ(a.signal_Hz, with_fixed_pattern(cfg, 1, PixelRates{1e6, 0, 0}, 5, 7).signal_Hz);
  EXPECT_NE(a.signal_Hz, with_fixed_pattern(cfg, 2, PixelRates{1e6, 0, 0}, 5, 7).signal_Hz);
}

TEST(SpadNonideal, DarkCountRateDoublesEveryDoublingTemperature) {
  ParamSet p = load_preset_file(std::string(RANGESIM_SOURCE_DIR) + "/presets/tof-spad.toml");
  const double at_ref = tof_spad_from_params(p).spad.dark_count_rate_Hz;
  const ParamSchema& schema = tof_spad_schema();
  p.set_from_text("spad.temperature_K=318", "--set", schema);  // 2 x 9 K above the reference
  EXPECT_NEAR(tof_spad_from_params(p).spad.dark_count_rate_Hz / at_ref, 4.0, 1e-12);
  p.set_from_text("spad.temperature_K=273", "--set", schema);
  EXPECT_NEAR(tof_spad_from_params(p).spad.dark_count_rate_Hz / at_ref, std::exp2(-27.0 / 9.0), 1e-12);
}

// A pixel of a chip with a fixed pattern: its PDE 0.6 of the mean (PRNU) and 2e5 counts/s more
// dark counts (DSNU), the three columns sharing its TDC at the mean. Golden's per-pixel model
// (SpadModel::evaluate_pixel: the renewal chain with our pixel a class of its own) against the
// kernel with those rates: the estimator's mean within 4.5 standard errors and its variance within
// the chi-square band (+10 % for the delta method), 600 independent groups; and both far from the
// mean pixel (the test can fail).
TEST(SpadNonideal, PixelOffTheMeanIsGoldensPixel) {
  TofSpadConfig cfg = preset_config();
  cfg.histogram.integration_time_s = 5e-3;
  const double signal = 4e4, background = 1e5, d = 2.0, rt = 2 * d / phys::kSpeedOfLight_m_per_s;
  const golden::spad::SpadModel model(cfg);
  const golden::spad::SpadModel::PixelDraw draw{0.6, 2e5};
  const golden::spad::PointResult g = model.evaluate_pixel(signal, background, d, model.estimator(), draw);
  const golden::spad::PointResult mean_pixel = model.evaluate_pixel(signal, background, d, model.estimator(), {});
  ASSERT_TRUE(g.moments.defined);
  TofSpadKernelOptions opt;
  opt.seed = 5;
  opt.noise.afterpulse = false;  // the golden histogram bounds afterpulses, does not model them
  const int groups = 600, cpt = cfg.tdc.columns_per_tdc;
  const TofSpadKernel k(cfg, 1, groups * cpt, opt);
  const RateSource rates = [&](int, int c) {
    return c % cpt == 0 ? PixelRates{signal * draw.gain, background * draw.gain, rt, draw.dark_extra_Hz}
                        : PixelRates{signal, background, rt};
  };
  double sum = 0, sum2 = 0;
  for (int gi = 0; gi < groups; ++gi) {
    const GroupHistogram gh = k.simulate_group(0, 0, gi, rates);
    const auto t = k.estimate(gh.events[0], gh.armed);
    ASSERT_TRUE(t.has_value());
    sum += *t, sum2 += *t * *t;
  }
  const double mean = sum / groups, var = (sum2 - groups * mean * mean) / (groups - 1);
  const double se = std::sqrt(g.moments.var_s2 / groups);
  std::printf(
      "pixel (gain %.1f, dark +%.0f/s): kernel mean %.3f ps sd %.3f ps; golden %.3f ps sd %.3f ps; mean pixel sd %.3f "
      "ps\n",
      draw.gain, draw.dark_extra_Hz, (mean - rt) * 1e12, std::sqrt(var) * 1e12, (g.moments.mean_s - rt) * 1e12,
      std::sqrt(g.moments.var_s2) * 1e12, std::sqrt(mean_pixel.moments.var_s2) * 1e12);
  EXPECT_NEAR(mean, g.moments.mean_s, 4.5 * se);
  EXPECT_NEAR(var / g.moments.var_s2, 1.0, 5 * std::sqrt(2.0 / (groups - 1)) + 0.10);
  EXPECT_GT(g.moments.var_s2, 1.5 * mean_pixel.moments.var_s2);  // the drawn pixel is much noisier
}

// The estimator's mean over `groups` independent groups (the frame keys them) of the pixel at
// (row, column 0) of a kernel whose rates are `rates`.
struct Estimates {
  double mean = 0, sd = 0;
  int n = 0;
};
Estimates kernel_estimates(const TofSpadConfig& cfg, const RateSource& rates, int rows, int row, int groups) {
  TofSpadKernelOptions opt;
  opt.seed = 11;
  opt.noise.afterpulse = false;  // the golden histogram bounds afterpulses, does not model them
  const TofSpadKernel k(cfg, rows, cfg.tdc.columns_per_tdc, opt);
  double sum = 0, sum2 = 0;
  Estimates e;
  for (int g = 0; g < groups; ++g) {
    const GroupHistogram gh = k.simulate_group(static_cast<std::uint64_t>(g), row, 0, rates);
    const auto t = k.estimate(gh.events[0], gh.armed);
    if (!t) continue;
    sum += *t, sum2 += *t * *t, ++e.n;
  }
  e.mean = sum / e.n, e.sd = std::sqrt((sum2 - e.n * e.mean * e.mean) / (e.n - 1));
  return e;
}

// A second return 30 % as strong, 4.5 cm further (300 ps: inside the peak window) pulls the
// centroid late. Golden (the second return in its arrivals, the renewal chain on the sum) against
// the kernel (the pixel kernel taking both echoes, systemc/tof_spad/nonideal_rates.h): the means
// within 4.5 standard errors, and far from the single return's.
TEST(SpadNonideal, MultipathBiasesTheRangeAsGoldenSays) {
  TofSpadConfig cfg = preset_config();
  cfg.histogram.integration_time_s = 5e-3;
  cfg.multipath.relative_amplitude = 0.3, cfg.multipath.extra_path_m = 0.045;
  const double signal = 4e4, background = 1e5, d = 2.0, rt = 2 * d / phys::kSpeedOfLight_m_per_s;
  const golden::spad::SpadModel model(cfg);
  const golden::spad::PointResult g = model.evaluate(signal, background, d);
  TofSpadConfig single = cfg;
  single.multipath.relative_amplitude = 0;
  const golden::spad::PointResult g1 = golden::spad::SpadModel(single).evaluate(signal, background, d);
  const RateSource rates = chip_rates(
      cfg, 1,
      [&](int, int) {
        return PixelRates{signal, background, rt};
      },
      1, 4);
  ASSERT_EQ(rates(0, 0).echoes.size(), 1u);
  const Estimates k = kernel_estimates(cfg, rates, 1, 0, 600);
  const double se = std::sqrt(g.moments.var_s2 / k.n);
  std::printf("multipath 0.3 at +4.5 cm: bias kernel %.3f mm, golden %.3f mm (single return %.3f mm), se %.3f mm\n",
              (k.mean - rt) * 0.5e3 * phys::kSpeedOfLight_m_per_s, g.bias_m * 1e3, g1.bias_m * 1e3,
              se * 0.5e3 * phys::kSpeedOfLight_m_per_s);
  EXPECT_EQ(k.n, 600);
  EXPECT_NEAR(k.mean, g.moments.mean_s, 4.5 * se);
  EXPECT_GT(std::fabs(g1.moments.mean_s - k.mean), 10 * se);
}

// A depth step (2.00 m above row 8, 2.06 m from it) through a Gaussian point spread of 1 pixel:
// row 8 also receives the echo of row 7, 400 ps earlier (a flying pixel, its range between the
// surfaces). Golden sums the returns the optics give that pixel (SpadModel::evaluate_returns);
// the kernel takes them as two echoes. Means within 4.5 standard errors; the range lies between
// the surfaces, several standard errors from both.
TEST(SpadNonideal, BlurMakesAFlyingPixelAtADepthStep) {
  TofSpadConfig cfg = preset_config();
  cfg.histogram.integration_time_s = 5e-3;
  cfg.blur.psf = PsfKind::Gaussian, cfg.blur.gaussian_sigma_px = 1.0;
  const double signal = 4e4, background = 1e5, near_m = 2.0, far_m = 2.06;
  const int rows = 16, step = 8;
  const auto rt = [](double d) { return 2 * d / phys::kSpeedOfLight_m_per_s; };
  const RateSource rates = chip_rates(
      cfg, 1,
      [&](int r, int) {
        return PixelRates{signal, background, rt(r < step ? near_m : far_m)};
      },
      rows, 4);
  const PixelRates px = rates(step, 0);
  ASSERT_FALSE(px.echoes.empty());
  std::vector<golden::spad::SpadModel::SignalReturn> returns{{px.signal_Hz, far_m}};
  for (const SpadEcho& e : px.echoes)
    returns.push_back({e.signal_Hz, 0.5 * e.round_trip_s * phys::kSpeedOfLight_m_per_s});
  const golden::spad::SpadModel model(cfg);
  const golden::spad::PointResult g = model.evaluate_returns(returns, px.background_Hz, far_m);
  const Estimates k = kernel_estimates(cfg, rates, rows, step, 600);
  const double half_c = 0.5 * phys::kSpeedOfLight_m_per_s, se = std::sqrt(g.moments.var_s2 / k.n);
  const double range_k = half_c * k.mean, range_g = half_c * g.moments.mean_s;
  std::printf("depth step 2.00 | 2.06 m, PSF 1 px: row 8 reads %.4f m (kernel), %.4f m (golden), se %.2f mm\n", range_k,
              range_g, half_c * se * 1e3);
  EXPECT_NEAR(k.mean, g.moments.mean_s, 4.5 * se);
  EXPECT_GT(range_g, near_m + 5 * half_c * se);
  EXPECT_LT(range_g, far_m - 5 * half_c * se);
}

}  // namespace
}  // namespace rangesim::systemc::spad
