// Front end of the tof-lockin golden model: pulse split over the gate windows, FD charge, ADC
// moments (golden/tof_lockin/pulse_timing.h, tap_charge.h, adc_moments.h).
#include <gtest/gtest.h>

#include <cmath>

#include "core/physics.h"
#include "golden/tof_lockin/adc_moments.h"
#include "golden/tof_lockin/pulse_timing.h"
#include "golden/tof_lockin/tap_charge.h"
#include "lockin_test_util.h"

namespace rangesim::golden {

using test::lockin_config;

TEST(LockinPulse, RectangularSplitIsEq217And218) {
  const TofLockinConfig cfg = lockin_config();
  const double T0 = cfg.source.pulse_width_s;
  for (double td : {0.0, 1e-9, 6.67e-9, 50e-9, 99e-9, 100e-9}) {
    const PulseSplit s = split_pulse(cfg.source, td);
    EXPECT_NEAR(s.tap1_s, T0 - td, 1e-18) << td;  // N1 ~ T0 - T_D
    EXPECT_NEAR(s.tap2_s, td, 1e-18) << td;       // N2 ~ T_D
    EXPECT_NEAR(s.drain_s, 0.0, 1e-18) << td;
  }
  // Beyond T0 the pulse leaves PHASE2 into the drain and N1 = 0: out of range.
  const PulseSplit late = split_pulse(cfg.source, 130e-9);
  EXPECT_DOUBLE_EQ(late.tap1_s, 0.0);
  EXPECT_NEAR(late.tap2_s, 70e-9, 1e-18);
  EXPECT_NEAR(late.drain_s, 30e-9, 1e-18);
  EXPECT_FALSE(delay_in_range(cfg.source, 130e-9));
  EXPECT_FALSE(delay_in_range(cfg.source, -1e-12));
  EXPECT_TRUE(delay_in_range(cfg.source, round_trip_delay_s(max_range_m(cfg.source))));
  EXPECT_NEAR(max_range_m(cfg.source), 14.9896229, 1e-6);
  EXPECT_NEAR(repetition_period_s(cfg.source), 1e-6, 1e-18);
}

TEST(LockinPulse, TrapezoidKeepsAreaAndMonotonicRatio) {
  TofLockinConfig cfg = lockin_config();
  cfg.source.rise_time_s = 8e-9;  // 10 ns linear ramps
  EXPECT_NEAR(pulse_area_before_s(cfg.source, 1e-6), cfg.source.pulse_width_s, 1e-18);
  EXPECT_NEAR(pulse_area_before_s(cfg.source, 5e-9), 5e-9 * 5e-9 / 20e-9, 1e-20);  // t^2 / (2 r)
  double prev = -1;
  for (int i = 0; i <= 100; ++i) {
    const PulseSplit s = split_pulse(cfg.source, i * 1e-9);
    EXPECT_NEAR(s.tap1_s + s.tap2_s + s.drain_s, 100e-9, 1e-18);
    const double ratio = s.tap2_s / (s.tap1_s + s.tap2_s);
    EXPECT_GT(ratio, prev);  // still one-to-one on the delay
    prev = ratio;
  }
}

// Duty 0.5, 8 ns rise (10 ns ramps), T_D = T0: the received pulse covers [T0, 2 T0 + r]; its
// falling ramp [2 T0, 2 T0 + r] (area r / 2) arrives in the next period's PHASE1 and goes to FD1.
// Periods 1 .. N-1 receive it; the last pulse's tail falls into the readout and is not collected.
TEST(LockinCharge, PulseTailPastThePeriodGoesToTheNextPhase1) {
  TofLockinConfig cfg = lockin_config();
  cfg.source.duty_cycle = 0.5;
  cfg.source.rise_time_s = 8e-9;
  cfg.pixel.drain_efficiency = 0.9;  // a drained tail would leak 5 % into each FD
  const double q = phys::kElementaryCharge_C, n = 50, T0 = 100e-9, r = 10e-9, is = 1e-9;
  const FrameCharge c = frame_charge(cfg, is, 0.0, T0);
  EXPECT_NEAR(c.signal_e[0], is * (n - 1) * r / 2 / q, 1e-9);
  EXPECT_NEAR(c.signal_e[1], is * n * (T0 - r / 2) / q, 1e-6);
  EXPECT_NEAR(c.light_common_e, 0.0, 1e-9);  // nothing reached the (empty) PHASE3
  EXPECT_NEAR(window_light_in_period_s(cfg.source, T0, 0.0, T0, 0), 0.0, 1e-24);
  EXPECT_NEAR(window_light_in_period_s(cfg.source, T0, 0.0, T0, 7), r / 2, 1e-22);
  // Duty 0.25: PHASE3 [2 T0, 4 T0] holds the whole tail, which is drained (leak to each FD).
  cfg.source.duty_cycle = 0.25;
  const FrameCharge d = frame_charge(cfg, is, 0.0, T0);
  EXPECT_NEAR(d.signal_e[0], 0.0, 1e-9);
  EXPECT_NEAR(d.light_common_e, 0.05 * is * n * r / 2 / q, 1e-6);
}

// The numerical integration behind the time-step knob: a ramp is integrated with an O(h^2)
// error, which falls with every step and vanishes in the limit; outside the pulse it is 0; step 0
// is the closed form.
TEST(LockinPulse, NumericalOverlapConvergesToTheClosedForm) {
  TofLockinConfig cfg = lockin_config();
  cfg.source.rise_time_s = 8e-9;          // ramps [0, 10 ns] and [100, 110 ns]
  const double a = 3.3e-9, b = 104.1e-9;  // a window cutting both ramps
  const double exact = pulse_area_before_s(cfg.source, b) - pulse_area_before_s(cfg.source, a);
  EXPECT_EQ(pulse_area_between_s(cfg.source, a, b, 0.0), exact);
  double prev = INFINITY;
  for (double h : {20e-9, 2e-9, 0.2e-9, 0.02e-9}) {
    const double e = std::fabs(pulse_area_between_s(cfg.source, a, b, h) - exact);
    EXPECT_LT(e, prev) << h;
    EXPECT_LE(e, 1.001 * 2 * h * h / (10e-9 * 8)) << h;  // midpoint rule: <= kinks x slope jump x h^2 / 8
    prev = e;
  }
  EXPECT_LT(prev, 1e-18);  // 1e-11 of the area: rounding of the 5000-term sum
  EXPECT_EQ(pulse_area_between_s(cfg.source, 120e-9, 300e-9, 1e-9), 0.0);
  EXPECT_EQ(pulse_area_between_s(cfg.source, -50e-9, -1e-9, 1e-9), 0.0);
  EXPECT_NEAR(pulse_area_between_s(cfg.source, -50e-9, 300e-9, 1e-9), 100e-9, 1e-21);  // whole area
}

TEST(LockinCharge, IdealPixelCollectsEq217SignalAndTwoWindowsOfBackground) {
  const TofLockinConfig cfg = lockin_config();
  const double q = phys::kElementaryCharge_C, n = 50, T0 = 100e-9;
  const FrameCharge c = frame_charge(cfg, 1e-9, 2e-10, 20e-9);
  EXPECT_NEAR(c.signal_e[0], 1e-9 * 80e-9 * n / q, 1e-6);
  EXPECT_NEAR(c.signal_e[1], 1e-9 * 20e-9 * n / q, 1e-6);
  EXPECT_DOUBLE_EQ(c.light_common_e, 0.0);                // eta = 1, drain efficiency 1
  EXPECT_NEAR(c.background_e, 2e-10 * T0 * n / q, 1e-6);  // PHASE3 fully drained
  EXPECT_NEAR(c.dark_e, 1e-15 * 1e-6 * n / q, 1e-9);
  // 1.5 nA -> 0.75 V of V1 + V2 with 10 fF (preset header).
  EXPECT_NEAR((c.signal_e[0] + c.signal_e[1]) * 1.5 * volts_per_electron(cfg, 0), 0.75, 1e-12);
}

TEST(LockinCharge, DeepElectronsAndDrainLeakageAreCommonMode) {
  TofLockinConfig cfg = lockin_config();
  cfg.pixel.charge_separation = 0.9;
  cfg.pixel.drain_efficiency = 0.99;
  const double q = phys::kElementaryCharge_C, n = 50, T0 = 100e-9, Trep = 1e-6;
  const double is = 1e-9, ib = 1e-10;
  const FrameCharge c = frame_charge(cfg, is, ib, 30e-9);
  EXPECT_NEAR(c.signal_e[0], 0.9 * is * 70e-9 * n / q, 1e-6);
  const double deep = 0.1 * is * T0 * n / q;
  const double leak = 0.005;
  EXPECT_NEAR(c.light_common_e, deep * T0 / Trep + leak * deep * (Trep - 2 * T0) / Trep, 1e-6);
  EXPECT_NEAR(c.background_e, ib * n * (T0 + leak * (Trep - 2 * T0)) / q, 1e-6);
}

// Brute-force moments of code x LSB for V ~ N(mu, sigma^2) over every code.
static QuantisedMoments brute(double mu, double sigma, double lsb, long long codes) {
  double e1 = 0, e2 = 0;
  for (long long k = 0; k < codes; ++k) {
    const double lo = k == 0 ? -1e300 : k * lsb, hi = k == codes - 1 ? 1e300 : (k + 1) * lsb;
    const double p =
        0.5 * (std::erfc((lo - mu) / (sigma * std::sqrt(2.0))) - std::erfc((hi - mu) / (sigma * std::sqrt(2.0))));
    e1 += p * k;
    e2 += p * k * k;
  }
  return {e1 * lsb, (e2 - e1 * e1) * lsb * lsb};
}

TEST(LockinAdc, MomentsMatchBruteForceInBothBranches) {
  const double lsb = 1.5 / 4096;
  for (double s_lsb : {0.05, 0.3, 1.0, 1.49, 1.5, 3.0, 20.0}) {
    for (double mu : {0.1003, 0.7001234}) {
      const QuantisedMoments a = quantised_moments(mu, s_lsb * lsb, lsb, 4096);
      const QuantisedMoments b = brute(mu, s_lsb * lsb, lsb, 4096);
      EXPECT_NEAR(a.mean_V, b.mean_V, 1e-12) << s_lsb << " " << mu;
      EXPECT_NEAR(a.var_V2, b.var_V2, 1e-6 * b.var_V2 + 1e-16) << s_lsb << " " << mu;
    }
  }
  // Clipping at both ends, and the deterministic truncation of eq. 4.9.
  const QuantisedMoments top = quantised_moments(1.6, 2 * lsb, lsb, 4096);
  EXPECT_NEAR(top.mean_V, 4095 * lsb, 1e-12);
  const QuantisedMoments edge = quantised_moments(1.5, 3 * lsb, lsb, 4096);
  const QuantisedMoments edge_ref = brute(1.5, 3 * lsb, lsb, 4096);
  EXPECT_NEAR(edge.mean_V, edge_ref.mean_V, 1e-12);
  EXPECT_NEAR(edge.var_V2, edge_ref.var_V2, 1e-6 * edge_ref.var_V2);
  EXPECT_NEAR(quantised_moments(-0.01, 1e-4, lsb, 4096).mean_V, 0.0, 1e-15);
  EXPECT_DOUBLE_EQ(quantised_moments(0.70012, 0.0, lsb, 4096).mean_V, std::floor(0.70012 / lsb) * lsb);
}

}  // namespace rangesim::golden
