// ls-conventional's fixed pattern: golden (a chip's comparator offsets as static noise, PRNU and
// DSNU averaged over the chip's draws; golden/common/fixed_pattern_activation.h) against the Monte
// Carlo of the clock-level kernels, which draws a chip per trial (systemc/ls_conventional/montecarlo.cpp).
// The stated test as test_mc_golden.cpp: golden within 2 half-widths of the MC's 95 % interval;
// 20000 trials put the std's half-width near 1 %, so golden 3 % off fails (checked per point).
#include <gtest/gtest.h>

#include <cmath>

#include "app/montecarlo/mc_stats.h"
#include "core/preset.h"
#include "golden/common/position_noise.h"
#include "golden/common/row_model.h"
#include "golden/ls_conventional/evaluation.h"
#include "mc_point_run.h"
#include "systemc/ls_conventional/montecarlo.h"

namespace rangesim::app::mc {
namespace {

using rangesim::mc::LsConventionalMc;
using rangesim::mc::SpotPlacement;

void expect_agrees(const McInterval& mc, double golden, const char* what) {
  EXPECT_LE(std::fabs(mc.value - golden), 2 * mc.half_width())
      << what << ": MC " << mc.value << " [" << mc.lo << ", " << mc.hi << "], golden " << golden;
}

void expect_catches_three_percent(const McInterval& mc, double golden, const char* what) {
  for (double f : {0.97, 1.03})
    EXPECT_GT(std::fabs(mc.value - f * golden), 2 * mc.half_width())
        << what << ": a golden " << f << " x " << golden << " would pass against MC " << mc.value;
}

LsConventionalConfig preset() { return ls_conventional_from_params(load_preset("ls-conventional")); }

// One key on at a fixed spot position: golden's bias and std against the MC, the 3 % companion, and
// the key's effect on the std (golden without it is far outside the MC's interval).
void check_fixed_spot(const LsConventionalConfig& cfg, double sig, double bg, double u, std::uint64_t index) {
  const golden::RowModel row = golden::make_row_model(cfg, sig, bg), plain = golden::make_row_model(preset(), sig, bg);
  const double x0 = row.centre_pixel - 0.5 + u;
  const golden::PositionMoments g = golden::position_moments(row, x0), g0 = golden::position_moments(plain, x0);
  ASSERT_TRUE(g.exact);
  const McPointStats s = run_mc_point(LsConventionalMc(cfg, SpotPlacement{u}), sig, bg, 20000, index);
  expect_agrees(s.p_detect, g.p_detect, "p_detect");
  expect_agrees(s.bias, g.mean_px - x0, "mean error (px)");
  expect_agrees(s.std, std::sqrt(g.var_px2), "std (px)");
  expect_catches_three_percent(s.std, std::sqrt(g.var_px2), "std (px)");
  EXPECT_GT(std::fabs(s.std.value - std::sqrt(g0.var_px2)), 4 * s.std.half_width()) << "the key has no visible effect";
}

TEST(McGoldenLsConvFixedPattern, ComparatorOffsetChipPerTrial) {
  LsConventionalConfig cfg = preset();
  cfg.fixed_pattern.comparator_offset_rms_V = 0.002;
  check_fixed_spot(cfg, 0.05, 0.003, 0.3, 41);
}

TEST(McGoldenLsConvFixedPattern, PrnuChipPerTrial) {
  LsConventionalConfig cfg = preset();
  cfg.fixed_pattern.prnu_fraction = 0.05;
  check_fixed_spot(cfg, 0.2, 0.01, 0.6, 42);
}

TEST(McGoldenLsConvFixedPattern, DsnuChipPerTrial) {
  LsConventionalConfig cfg = preset();
  cfg.fixed_pattern.dsnu_rms = 3e-12;  // 3.75 mV of dark swing rms (half the pixels clip at zero current)
  check_fixed_spot(cfg, 0.05, 0.003, 0.3, 43);
}

// PRNU x background against the tracking threshold's 10 mV margin: false activations of background
// pixels (outliers) that golden gives exactly, and the accuracy over spot positions without them.
TEST(McGoldenLsConvFixedPattern, PrnuFalseActivationsAtHighBackground) {
  LsConventionalConfig cfg = preset();
  cfg.fixed_pattern.prnu_fraction = 0.02;
  const golden::OperatingPoint g = golden::evaluate_point(cfg, 0.3, 0.15);
  ASSERT_EQ(g.detect, golden::Detect::Detectable);
  EXPECT_GT(g.p_outlier, 0.002);
  EXPECT_LT(golden::evaluate_point(preset(), 0.3, 0.15).p_outlier, 1e-6);
  const McPointStats s = run_mc_point(LsConventionalMc(cfg), 0.3, 0.15, 20000, 44);
  const double side =
      g.p_outlier >= s.p_outlier.value ? s.p_outlier.hi - s.p_outlier.value : s.p_outlier.value - s.p_outlier.lo;
  EXPECT_LE(std::fabs(g.p_outlier - s.p_outlier.value), 2 * side)
      << "P(outlier): MC " << s.p_outlier.value << " [" << s.p_outlier.lo << ", " << s.p_outlier.hi << "], golden "
      << g.p_outlier;
  expect_agrees(s.rms_clean, g.accuracy_clean_px, "accuracy without outliers (px)");
}

}  // namespace
}  // namespace rangesim::app::mc
