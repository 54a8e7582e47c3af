// The tof-lockin range-map validity (golden/tof_lockin/validity.h): the SNR and the range noise a
// pixel's own tap values give are golden's SNR of V1 + V2 and first-order range noise when the
// taps read their means, so a map's valid pixels and the evaluate grid's detectable points follow
// one rule (readout.min_snr and readout.max_range_noise_fraction).
#include <gtest/gtest.h>

#include <cmath>

#include "golden/tof_lockin/lockin_point.h"
#include "golden/tof_lockin/pulse_timing.h"
#include "golden/tof_lockin/tap_charge.h"
#include "golden/tof_lockin/validity.h"
#include "lockin_test_util.h"

namespace rangesim::golden {

namespace {

MeasuredTaps mean_taps(const TofLockinConfig& cfg, double signal_A, double background_A, double distance_m) {
  const FrameCharge c = frame_charge(cfg, signal_A, background_A, round_trip_delay_s(distance_m));
  MeasuredTaps t;
  for (int k = 0; k < 2; ++k)
    t.led_V[k] = tap_sample(cfg, k, c.total_e(k)).mean_V, t.ambient_V[k] = tap_sample(cfg, k, c.ambient_e()).mean_V;
  return t;
}

}  // namespace

TEST(LockinValidity, MeasuredSnrAtTheMeansIsGoldensSnr) {
  const TofLockinConfig cfg = test::lockin_config();
  int compared = 0;
  for (double signal : {2e-11, 1e-10, 5e-10, 1.5e-9})
    for (double background : {1e-14, 1e-11, 1e-9}) {
      const LockinPoint pt = evaluate_point(cfg, signal, background, 1.0, 1);
      if (pt.snr <= 0) continue;  // saturated or below threshold: no SNR computed
      EXPECT_NEAR(measured_snr(cfg, mean_taps(cfg, signal, background, 1.0)) / pt.snr, 1.0, 0.02)
          << signal << " A, " << background << " A";
      ++compared;
    }
  EXPECT_GE(compared, 8);
}

// The range noise a pixel computes from its own taps, read at their means, is golden's first-order
// noise of one range value: the map's validity and golden's detectability apply one criterion.
TEST(LockinValidity, MeasuredRangeNoiseAtTheMeansIsGoldensFirstOrderNoise) {
  const TofLockinConfig cfg = test::lockin_config();
  int compared = 0;
  for (double signal : {2e-11, 6e-11, 5e-10, 1.5e-9})
    for (double background : {1e-14, 1e-11, 1e-9})
      for (double distance : {1.0, 7.5, 14.0}) {
        const LockinPoint pt = evaluate_point(cfg, signal, background, distance, 1);
        if (pt.snr <= 0) continue;
        const MeasuredTaps t = mean_taps(cfg, signal, background, distance);
        EXPECT_NEAR(measured_range_noise_m(cfg, t) / pt.std_first_m, 1.0, 0.02)
            << signal << " A, " << background << " A, " << distance << " m";
        // Valid exactly where golden calls the point detectable (away from the edges).
        const double bound_m = cfg.readout.max_range_noise_fraction * max_range_m(cfg.source);
        if (std::fabs(measured_range_noise_m(cfg, t) / bound_m - 1) > 0.05 && pt.snr > 1.1 * cfg.readout.min_snr) {
          EXPECT_EQ(measured_range_valid(cfg, t), pt.detect == LockinDetect::Detectable) << signal << " " << distance;
        }
        ++compared;
      }
  EXPECT_GE(compared, 24);
}

TEST(LockinValidity, NoLightNoSnr) {
  const TofLockinConfig cfg = test::lockin_config();
  MeasuredTaps t = mean_taps(cfg, 0.0, 1e-10, 1.0);
  EXPECT_LT(measured_snr(cfg, t), 1.0);
  t.led_V[0] = t.ambient_V[0] - 0.01, t.led_V[1] = t.ambient_V[1] - 0.01;
  EXPECT_EQ(measured_snr(cfg, t), 0.0);
  EXPECT_TRUE(std::isinf(measured_range_noise_m(cfg, t)));
  EXPECT_FALSE(measured_range_valid(cfg, t));
}

}  // namespace rangesim::golden
