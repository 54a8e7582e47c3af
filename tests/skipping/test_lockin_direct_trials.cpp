// tof-lockin's direct Monte Carlo trials (config simulation.direct_trials): each trial's frames drawn
// by the pixel kernel, the column ADC and the range rule without stepping the sensor kernel's
// frame schedule. The schedule's cycles change no draw, so the trials must be the kernel's bit for
// bit: same detected flag, same error, for every trial, with and without the merged draws, with
// the chip's fixed pattern (a new chip every trial), a second return, frames averaged and without
// the ambient frame. The sweep's batches (McPointRunner::trials) are the same trials as one by one.
#include <gtest/gtest.h>

#include <vector>

#include "../systemc/tof_lockin/lockin_sc_test_util.h"
#include "systemc/tof_lockin/montecarlo.h"

namespace rangesim::systemc::lockin {
namespace {

void expect_same_trials(TofLockinConfig cfg, double signal_A, double background_A, int trials) {
  cfg.simulation.direct_trials = true;
  const auto direct = mc::TofLockinMc(cfg).point(signal_A, background_A, 99);
  cfg.simulation.direct_trials = false;
  const auto stepped = mc::TofLockinMc(cfg).point(signal_A, background_A, 99);
  int detected = 0;
  for (int t = 0; t < trials; ++t) {
    const mc::McTrial a = direct->trial(t), b = stepped->trial(t);
    ASSERT_EQ(a.detected, b.detected) << "trial " << t;
    if (!a.detected) continue;
    EXPECT_EQ(a.error, b.error) << "trial " << t;
    ++detected;
  }
  EXPECT_GT(detected, trials / 2);
}

TEST(LockinDirectTrials, BitIdenticalToKernelTrials) {
  const TofLockinConfig cfg = test::edited_config({});
  expect_same_trials(cfg, 3e-10, 1e-10, 3000);
  // Near the detection threshold some trials give no range: the flags must agree too.
  expect_same_trials(cfg, 1.2e-11, 1e-14, 3000);
}

TEST(LockinDirectTrials, BitIdenticalWithSeparateDraws) {
  TofLockinConfig cfg = test::edited_config({});
  cfg.simulation.merged_draws = false;
  expect_same_trials(cfg, 3e-10, 1e-10, 1000);
}

TEST(LockinDirectTrials, BitIdenticalWithFixedPatternMultipathAveragingNoAmbient) {
  expect_same_trials(test::edited_config({{"fixed_pattern", "tap_mismatch_fraction", "0.01"},
                                          {"fixed_pattern", "prnu_fraction", "0.02"},
                                          {"fixed_pattern", "dsnu_rms_A", "1e-15"}}),
                     3e-10, 1e-10, 300);
  expect_same_trials(
      test::edited_config({{"multipath", "relative_amplitude", "0.2"}, {"evaluation", "frames_averaged", "3"}}), 3e-10,
      1e-10, 500);
  expect_same_trials(
      test::edited_config({{"readout", "ambient_subtraction", "false"}, {"readout", "offset_calibration_V", "0.02"}}),
      3e-10, 1e-12, 500);
}

// Trials 0 .. 2999 of one point in batches of 7 against trial() one by one: flags and errors
// equal bit for bit; `detected` counts the trials with a range.
void expect_batches_equal_single(const TofLockinConfig& cfg, double signal_A, double background_A,
                                 long long* detected) {
  const mc::TofLockinMc model(cfg, true, 1500);  // code laws from trial 1500
  const auto single = model.point(signal_A, background_A, 7), batched = model.point(signal_A, background_A, 7);
  constexpr long long kTrials = 3000, kBatch = 7;
  std::vector<mc::McTrial> out(kTrials);
  for (long long t = 0; t < kTrials; t += kBatch) batched->trials(t, std::min(kBatch, kTrials - t), &out[t]);
  *detected = 0;
  for (long long t = 0; t < kTrials; ++t) {
    const mc::McTrial a = single->trial(t);
    ASSERT_EQ(a.detected, out[t].detected) << "trial " << t;
    ASSERT_EQ(a.outlier, out[t].outlier) << "trial " << t;
    if (!a.detected) continue;
    ASSERT_EQ(a.error, out[t].error) << "trial " << t;
    ++*detected;
  }
}

// The batched trials (the sweep's path; the code trials in one loop once their laws are drawn)
// equal trial() called one by one over batches that straddle both switches (alias tables from
// trial 1024, code laws from 1500), near the detection threshold too (some trials without a
// range), and with the fixed pattern (no code laws: the default loop).
TEST(LockinDirectTrials, BatchesEqualTrialsOneByOne) {
  const TofLockinConfig cfg = test::edited_config({});
  long long detected = 0;
  expect_batches_equal_single(cfg, 3e-10, 1e-10, &detected);
  EXPECT_EQ(detected, 3000);
  expect_batches_equal_single(cfg, 1.2e-11, 1e-14, &detected);
  EXPECT_GT(detected, 1500);
  EXPECT_LT(detected, 3000);  // the flags were put to the test
  expect_batches_equal_single(test::edited_config({{"fixed_pattern", "prnu_fraction", "0.02"}}), 3e-10, 1e-10,
                              &detected);
  EXPECT_EQ(detected, 3000);
}

}  // namespace
}  // namespace rangesim::systemc::lockin
