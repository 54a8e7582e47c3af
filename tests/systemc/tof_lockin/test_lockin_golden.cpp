// Noise-free clock-level simulation == the golden tap charges, voltages, codes
// and range (to floating rounding), at several delays and for ideal and
// non-ideal pixels; event skipping and aggregation give the same results as
// ticking.
#include <gtest/gtest.h>

#include <cmath>
#include <fmt/format.h>

#include "golden/tof_lockin/adc_moments.h"
#include "golden/tof_lockin/lockin_point.h"
#include "golden/tof_lockin/range_estimate.h"
#include "golden/tof_lockin/tap_charge.h"
#include "lockin_sc_test_util.h"

namespace rangesim::systemc::lockin {
namespace {

using test::Edit;

void check_against_golden(const TofLockinConfig& cfg, const LockinSimOptions& opt, double is, double ib, double L) {
  SCOPED_TRACE(
      fmt::format("I_s {:g} I_b {:g} L {:g} skip {} aggregate {}", is, ib, L, opt.event_skipping, opt.aggregate));
  TofLockinSensorKernel k(cfg, opt, 1, 2, test::uniform(2, is, ib, L), cfg.readout.ambient_subtraction ? 2 : 1);
  k.run();
  const golden::FrameCharge c = golden::frame_charge(cfg, is, ib, golden::round_trip_delay_s(L));
  const double lsb = golden::adc_lsb_V(cfg);
  const long long codes = 1LL << cfg.readout.adc_bits;
  double mu[2];
  for (int col = 0; col < 2; ++col)
    for (int t = 0; t < 2; ++t) {
      const golden::TapSample on = golden::tap_sample(cfg, t, c.total_e(t));
      EXPECT_NEAR(k.adc_input_V(0, 0, col, t), on.mean_V, 1e-12 * on.mean_V) << "tap " << t;
      const golden::QuantisedMoments q_on = golden::quantised_moments(on.mean_V, 0.0, lsb, codes);
      EXPECT_EQ(k.code(0, 0, col, t) * lsb, q_on.mean_V);
      mu[t] = q_on.mean_V - cfg.readout.offset_calibration_V;
      if (cfg.readout.ambient_subtraction) {
        const golden::TapSample off = golden::tap_sample(cfg, t, c.ambient_e());
        EXPECT_NEAR(k.adc_input_V(1, 0, col, t), off.mean_V, 1e-12 * off.mean_V);
        const golden::QuantisedMoments q_off = golden::quantised_moments(off.mean_V, 0.0, lsb, codes);
        EXPECT_EQ(k.code(1, 0, col, t) * lsb, q_off.mean_V);
        mu[t] -= q_off.mean_V;
      }
    }
  const golden::RangeMoments m = golden::range_moments(golden::max_range_m(cfg.source), mu[0], 0.0, mu[1], 0.0);
  EXPECT_NEAR(k.range_m(0, 0, 0), m.noise_free_m, 1e-12 * golden::max_range_m(cfg.source));
  EXPECT_EQ(k.range_m(0, 0, 0), k.range_m(0, 0, 1));
  // The unquantised ratio is the true distance (ideal pixel) within the
  // LSB-limited bias.
  if (cfg.pixel.charge_separation == 1.0 && cfg.pixel.drain_efficiency == 1.0 && cfg.source.rise_time_s == 0.0) {
    EXPECT_NEAR(k.range_m(0, 0, 0), L, 0.05);
  }
}

const double kDistances[] = {0.3, 1.0, 3.7, 7.5, 11.0, 14.5};

TEST(LockinGolden, NoiseFreeIdealPixelAtSeveralDelays) {
  const TofLockinConfig cfg = test::edited_config({{"pixel", "rows", "2"}});
  for (double L : kDistances)
    for (bool aggregate : {false, true})
      check_against_golden(cfg, LockinSimOptions{false, true, aggregate, 1}, 1e-9, 1e-10, L);
}

TEST(LockinGolden, NoiseFreeNonIdealPixelRiseTimeNoAmbient) {
  const TofLockinConfig cfg = test::edited_config({{"pixel", "rows", "2"},
                                                   {"pixel", "charge_separation", "0.9"},
                                                   {"pixel", "drain_efficiency", "0.98"},
                                                   {"source", "rise_time_s", "8e-9"},
                                                   {"readout", "ambient_subtraction", "false"},
                                                   {"readout", "offset_calibration_V", "0.02"}});
  for (double L : kDistances) check_against_golden(cfg, LockinSimOptions{false, true, false, 1}, 6e-10, 2e-11, L);
}

TEST(LockinGolden, NoiseFreeShortPulse) {
  const TofLockinConfig cfg = test::edited_config(
      {{"pixel", "rows", "2"}, {"source", "pulse_width_s", "10e-9"}, {"gates", "accumulations_per_frame", "500"}});
  for (double L : {0.2, 0.75, 1.4}) check_against_golden(cfg, LockinSimOptions{false, true, true, 1}, 1e-9, 1e-11, L);
}

TEST(LockinGolden, DepthStepThroughTheWholeRange) {
  // Range from the noise-free simulation follows the distance within the
  // quantisation bias.
  const TofLockinConfig cfg = test::edited_config({{"pixel", "rows", "1"}});
  std::vector<LockinPixelStimulus> st;
  for (int i = 0; i < 20; ++i) st.push_back({1.2e-9, 0, golden::round_trip_delay_s(0.5 + 0.7 * i)});
  TofLockinSensorKernel k(cfg, LockinSimOptions{false, true, true, 1}, 1, 20, st, 2);
  k.run();
  for (int i = 0; i < 20; ++i) EXPECT_NEAR(k.range_m(0, 0, i), 0.5 + 0.7 * i, 0.02) << i;
}

void expect_identical(const TofLockinSensorKernel& a, const TofLockinSensorKernel& b, long long frames) {
  for (long long f = 0; f < frames; ++f)
    for (int r = 0; r < a.rows(); ++r)
      for (int c = 0; c < a.columns(); ++c)
        for (int t = 0; t < 2; ++t) {
          EXPECT_EQ(a.code(f, r, c, t), b.code(f, r, c, t));
          EXPECT_EQ(a.adc_input_V(f, r, c, t), b.adc_input_V(f, r, c, t));  // bit for bit
        }
  ASSERT_EQ(a.frame_records().size(), b.frame_records().size());
  for (std::size_t i = 0; i < a.frame_records().size(); ++i)
    for (int p = 0; p < kPhaseCount; ++p) EXPECT_EQ(a.frame_records()[i].cycles[p], b.frame_records()[i].cycles[p]);
}

TEST(LockinSkipping, EventSkippingEqualsTickingWithNoise) {
  const TofLockinConfig cfg = test::edited_config({{"pixel", "rows", "3"},
                                                   {"gates", "accumulations_per_frame", "5"},
                                                   {"pixel", "drain_efficiency", "0.95"},
                                                   {"source", "rise_time_s", "8e-9"},
                                                   {"readout", "adc_conversion_cycles", "300"}});
  std::vector<LockinPixelStimulus> st;
  for (int i = 0; i < 6; ++i) st.push_back({2e-9, 3e-10, golden::round_trip_delay_s(1.0 + 2.2 * i)});
  const LockinSimOptions skip{true, true, false, 7}, tick{true, false, false, 7};
  TofLockinSensorKernel a(cfg, skip, 2, 3, st, 4), b(cfg, tick, 2, 3, st, 4);
  a.run(), b.run();
  expect_identical(a, b, 4);
  EXPECT_LT(a.events() * 20, b.events());  // the skip is real
  EXPECT_EQ(a.time_s(), b.time_s());
}

TEST(LockinSkipping, EventSkippingEqualsTickingNoiseFree) {
  const TofLockinConfig cfg = test::edited_config({{"pixel", "rows", "2"}, {"gates", "accumulations_per_frame", "3"}});
  const auto st = test::uniform(2, 1e-9, 1e-10, 4.2);
  TofLockinSensorKernel a(cfg, {false, true, false, 1}, 1, 2, st, 2), b(cfg, {false, false, false, 1}, 1, 2, st, 2);
  a.run(), b.run();
  expect_identical(a, b, 2);
}

TEST(LockinSkipping, AggregationEqualsPerPeriodNoiseFreeToRounding) {
  const TofLockinConfig cfg = test::edited_config({{"pixel", "rows", "2"}, {"pixel", "drain_efficiency", "0.9"}});
  const auto st = test::uniform(2, 1e-9, 1e-10, 6.1);
  TofLockinSensorKernel a(cfg, {false, true, true, 1}, 1, 2, st, 2), b(cfg, {false, true, false, 1}, 1, 2, st, 2);
  a.run(), b.run();
  for (int t = 0; t < 2; ++t) {
    EXPECT_NEAR(a.adc_input_V(0, 0, 0, t), b.adc_input_V(0, 0, 0, t), 1e-12);
    EXPECT_EQ(a.code(0, 0, 0, t), b.code(0, 0, 0, t));
  }
}

TEST(LockinSkipping, SameSeedSameBitsOtherSeedOtherBits) {
  const TofLockinConfig cfg = test::edited_config({{"pixel", "rows", "2"}});
  const auto st = test::uniform(4, 1e-9, 1e-10, 4.2);
  TofLockinSensorKernel a(cfg, {true, true, true, 3}, 2, 2, st, 2), b(cfg, {true, true, true, 3}, 2, 2, st, 2),
      c(cfg, {true, true, true, 4}, 2, 2, st, 2);
  a.run(), b.run(), c.run();
  expect_identical(a, b, 2);
  EXPECT_NE(a.adc_input_V(0, 0, 0, 0), c.adc_input_V(0, 0, 0, 0));
  EXPECT_NE(a.adc_input_V(0, 0, 0, 0), a.adc_input_V(0, 0, 1, 0));  // pixels have their own streams
}

}  // namespace
}  // namespace rangesim::systemc::lockin
