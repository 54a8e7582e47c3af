// Range estimate and operating point (golden/tof_lockin/range_estimate.h, lockin_point.h).
#include <gtest/gtest.h>

#include <cmath>

#include "core/physics.h"
#include "golden/tof_lockin/lockin_point.h"
#include "golden/tof_lockin/pulse_timing.h"
#include "golden/tof_lockin/range_estimate.h"
#include "golden/tof_lockin/tap_charge.h"
#include "lockin_test_util.h"

namespace rangesim::golden {

using test::lockin_config;

// Noise-free readout apart from signal shot noise: no kTC, read or dark noise, no ambient frame,
// fine ADC, offset calibrated exactly.
static TofLockinConfig shot_only() {
  TofLockinConfig c = lockin_config();
  c.readout.cds_enabled = true;
  c.readout.ambient_subtraction = false;
  c.readout.offset_calibration_V = c.pixel.offset_voltage_V;
  c.readout.adc_bits = 24;
  c.readout.adc_full_scale_V = 2.0;
  c.noise.read_noise_V = 0;
  c.nonideal.offset_shot_noise = false;  // signal shot noise alone
  c.noise.dark_current_A = 0;
  return c;
}

TEST(LockinEstimate, FirstOrderIsTheReferenceFormula) {
  // The first-order lock-in formula: sigma_L = (c T0/2) sqrt(N1^2 var(N2) + N2^2 var(N1)) / (N1+N2)^2,
  // var(N_i) = N_i + 2 N_amb + 2 n_read^2.
  const double K = 14.9896229, n1 = 30000, n2 = 9000, namb = 5000, nread = 45;
  const double v1 = n1 + 2 * namb + 2 * nread * nread, v2 = n2 + 2 * namb + 2 * nread * nread;
  const RangeMoments m = range_moments(K, n1, v1, n2, v2);
  const double ref = K * std::sqrt(n1 * n1 * v2 + n2 * n2 * v1) / std::pow(n1 + n2, 2);
  EXPECT_NEAR(std::sqrt(m.var_first_m2), ref, 1e-12 * ref);
  EXPECT_NEAR(m.noise_free_m, K * n2 / (n1 + n2), 1e-12);
  // The second-order terms are O(1/SNR^2) relative.
  EXPECT_NEAR(m.var_m2 / m.var_first_m2, 1.0, 10.0 / (m.snr * m.snr));
}

TEST(LockinEstimate, ShotLimitedMidRangeIsCT0Over4SqrtN) {
  const double K = 14.9896229, ns = 40000;
  const RangeMoments m = range_moments(K, ns / 2, ns / 2, ns / 2, ns / 2);
  EXPECT_NEAR(std::sqrt(m.var_first_m2), 2 * K / (4 * std::sqrt(ns)), 1e-12);
  EXPECT_NEAR(m.mean_m, K / 2, 1e-12);  // symmetric: no second-order bias
}

TEST(LockinPoint, ShotOnlyAt1p4VAnd1mIsThe126mmOfTable51) {
  const TofLockinConfig c = shot_only();
  const double L = 1.0, is = signal_current_for_voltage_A(c, 1.4, L);
  const LockinPoint p = evaluate_point(c, is, 0.0, L, 1);
  ASSERT_EQ(p.detect, LockinDetect::Detectable);
  EXPECT_NEAR(p.signal_V, 1.4, 1e-12);
  const double ns = 1.4 * 10e-15 / phys::kElementaryCharge_C, x = round_trip_delay_s(L) / 100e-9;
  EXPECT_NEAR(p.std_first_m, 14.9896229 * std::sqrt(x * (1 - x) / ns), 1e-6);
  EXPECT_NEAR(p.std_m, 0.01265, 0.00005);
  EXPECT_LT(std::fabs(p.bias_m), 1e-5);
}

TEST(LockinPoint, DetectReasons) {
  const TofLockinConfig c = lockin_config();
  EXPECT_EQ(evaluate_point(c, 1e-9, 1e-12, 16.0, 1).detect, LockinDetect::OutOfRange);
  EXPECT_EQ(evaluate_point(c, 1e-9, 1e-12, -0.1, 1).detect, LockinDetect::OutOfRange);
  EXPECT_EQ(evaluate_point(c, 1e-9, 5e-9, 1.0, 1).detect, LockinDetect::Saturated);
  EXPECT_EQ(evaluate_point(c, 5e-12, 1e-14, 1.0, 1).detect, LockinDetect::BelowThreshold);
  // Above the 5 mV threshold but under 3 sigma of the readout noise floor.
  EXPECT_EQ(evaluate_point(c, 1.05e-11, 1e-14, 1.0, 1).detect, LockinDetect::NoiseLimited);
  EXPECT_EQ(evaluate_point(c, 1e-9, 1e-12, 1.0, 1).detect, LockinDetect::Detectable);
  EXPECT_STREQ(to_string(LockinDetect::NoiseLimited), "noise_limited");
  // SNR 3-13 at 1 m: a range, but with more noise than the bound (5 % of c T0 / 2 = 0.75 m).
  EXPECT_EQ(evaluate_point(c, 3e-11, 1e-14, 1.0, 1).detect, LockinDetect::RangeErrorUnbounded);
  EXPECT_STREQ(to_string(LockinDetect::RangeErrorUnbounded), "range_error_unbounded");
}

// The verdict on both sides of the range-noise bound: the signal where one range value's rms noise
// (first order) is readout.max_range_noise_fraction x c T0 / 2, found by bisection; 1e-6 above it
// the point is detectable, 1e-6 below it range_error_unbounded. The bound follows the key.
TEST(LockinPoint, RangeNoiseBoundOnBothSides) {
  for (double fraction : {0.05, 0.02}) {
    TofLockinConfig c = lockin_config();
    c.readout.max_range_noise_fraction = fraction;
    const double bound_m = fraction * max_range_m(c.source);
    double lo = 1.05e-11, hi = 1.5e-9;  // noise above the bound at lo, below at hi
    ASSERT_GT(evaluate_point(c, lo, 1e-12, 3.0, 1).std_first_m, bound_m);
    for (int i = 0; i < 100; ++i) {
      const double mid = std::sqrt(lo * hi);
      (evaluate_point(c, mid, 1e-12, 3.0, 1).std_first_m > bound_m ? lo : hi) = mid;
    }
    const LockinPoint above = evaluate_point(c, hi * (1 + 1e-6), 1e-12, 3.0, 1);
    const LockinPoint below = evaluate_point(c, hi * (1 - 1e-6), 1e-12, 3.0, 1);
    EXPECT_EQ(above.detect, LockinDetect::Detectable) << fraction;
    EXPECT_EQ(below.detect, LockinDetect::RangeErrorUnbounded) << fraction;
    EXPECT_NEAR(above.std_first_m / bound_m, 1.0, 1e-4);
    EXPECT_GT(below.snr, c.readout.min_snr);  // not the SNR rule
  }
}

TEST(LockinPoint, AveragingDividesOnlyTheVariance) {
  const TofLockinConfig c = lockin_config();
  const LockinPoint p1 = evaluate_point(c, 3e-10, 1e-10, 2.0, 1), p25 = evaluate_point(c, 3e-10, 1e-10, 2.0, 25);
  EXPECT_NEAR(p25.accuracy_m * p25.accuracy_m, p1.bias_m * p1.bias_m + p1.std_m * p1.std_m / 25, 1e-15);
  EXPECT_LT(std::fabs(p1.bias_m), 0.01 * p1.std_m);  // ambient frame cancels the offsets
}

TEST(LockinPoint, OffsetMiscalibrationBiasWithoutAmbientFrame) {
  TofLockinConfig c = shot_only();
  c.readout.offset_calibration_V = c.pixel.offset_voltage_V - 0.005;  // 5 mV left in each tap
  const double L = 3.0, is = signal_current_for_voltage_A(c, 0.5, L);
  const LockinPoint p = evaluate_point(c, is, 0.0, L, 1);
  // L' = K (b + d) / (a + b + 2 d), a + b = 0.5 V, b = 0.5 x / 1 with x = T_D / T0.
  const double K = max_range_m(c.source), x = round_trip_delay_s(L) / c.source.pulse_width_s;
  const double expect = K * (0.5 * x + 0.005) / (0.5 + 0.010) - L;
  EXPECT_NEAR(p.bias_m, expect, 2e-4);
  EXPECT_GT(p.bias_m, 0.0);  // towards mid-range
  // Fixed-pattern noise without the ambient frame: rms over pixels.
  c.noise.fixed_pattern_rms_V = 1e-3;
  const LockinPoint f = evaluate_point(c, is, 0.0, L, 1);
  EXPECT_NEAR(
      f.fpn_m,
      K * std::sqrt(std::pow(0.5 * x + 0.005, 2) + std::pow(0.5 * (1 - x) + 0.005, 2)) / std::pow(0.51, 2) * 1e-3,
      1e-5);
}

}  // namespace rangesim::golden
