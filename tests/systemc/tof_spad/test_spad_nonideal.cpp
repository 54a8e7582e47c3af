// tof-spad's fixed pattern on the kernels' inputs (systemc/tof_spad/nonideal_rates.h) and the
// temperature law of the dark count rate (core/nonideal.h).
#include <gtest/gtest.h>

#include <cmath>

#include "core/preset.h"
#include "core/schemas.h"
#include "core/tof_spad/config.h"
#include "systemc/tof_spad/nonideal_rates.h"

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

}  // namespace
}  // namespace rangesim::systemc::spad
