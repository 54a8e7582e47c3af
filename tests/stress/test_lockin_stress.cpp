// Stress and property tests of tof-lockin (label: stress): the golden operating point and the
// clock-level sensor kernel over extreme but legal inputs (T0 1 ps .. 1 ms, N_acc 1 .. 1e9, ADC
// 1 .. 16 bits, signal and background over 1e-18 .. 1 A). Invariants:
//   - no NaN/Inf in any LockinPoint field; rms values >= 0; a zero denominator (nothing left of
//     the signal) is an explicit below_threshold, never a division by zero;
//   - more signal never loses detection below saturation;
//   - more background never improves the first-order noise where the ADC is fine (ambient
//     subtracted, LSB far below the noise);
//   - the noise-free kernel's ADC input equals golden's mean tap voltage (exact), at any
//     accumulation count (aggregated) and clock grid;
//   - 95% confidence intervals of the kernel's mean tap values cover golden's mean ~95% of the time;
//   - hazard: 1e9 aggregated accumulations of a strong signal overflowed the integer Poisson draw.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <cmath>

#include "core/physics.h"
#include "golden/tof_lockin/adc_moments.h"
#include "golden/tof_lockin/lockin_point.h"
#include "golden/tof_lockin/pulse_timing.h"
#include "golden/tof_lockin/tap_charge.h"
#include "stress_gen.h"
#include "stress_print.h"
#include "systemc/tof_lockin/sensor_kernel.h"

namespace rangesim::golden {
namespace {

using stress::log_uniform;
using stress::log_uniform_or_zero;

bool finite(double v) { return std::isfinite(v); }

// Legal configuration (core/tof_lockin/schema.cpp ranges), T0 1 ps .. 1 ms.
rc::Gen<TofLockinConfig> lockin_config_gen() {
  return rc::gen::exec([] {
    TofLockinConfig c;
    c.pixel.fd1_capacitance_F = *log_uniform(1e-18, 1e-9);
    c.pixel.fd2_capacitance_F = *rc::gen::oneOf(rc::gen::just(c.pixel.fd1_capacitance_F), log_uniform(1e-18, 1e-9));
    c.pixel.source_follower_gain = *log_uniform(1e-3, 10.0);
    c.pixel.saturation_voltage_V = *log_uniform(1e-3, 10.0);
    c.pixel.offset_voltage_V = *log_uniform_or_zero(1e-6, 1.0);
    c.pixel.charge_separation = *rc::gen::element(0.5, 0.9, 1.0);
    c.pixel.drain_efficiency = *rc::gen::element(0.0, 0.9, 1.0);
    c.source.pulse_width_s = *log_uniform(1e-12, 1e-3);
    c.source.duty_cycle = *rc::gen::element(0.5, 0.25, 0.1, 0.001);
    c.source.rise_time_s = *rc::gen::element(0.0, 0.1, 0.5) * c.source.pulse_width_s;
    c.gates.accumulations_per_frame = std::llround(*log_uniform(1.0, 1e9));
    c.readout.adc_bits = *rc::gen::inRange(1, 17);
    c.readout.adc_full_scale_V = *log_uniform(1e-3, 10.0);
    c.readout.detection_threshold_V = *log_uniform(1e-9, 1.0);
    c.readout.min_snr = *log_uniform(1e-3, 1e3);
    c.readout.cds_enabled = *rc::gen::arbitrary<bool>();
    c.readout.ambient_subtraction = *rc::gen::arbitrary<bool>();
    c.readout.offset_calibration_V =
        *rc::gen::oneOf(rc::gen::just(0.0), rc::gen::just(c.pixel.offset_voltage_V), log_uniform(1e-6, 1.0));
    c.noise.temperature_K = *log_uniform(1e-3, 500.0);
    c.noise.dark_current_A = *log_uniform_or_zero(1e-18, 1e-9);
    c.noise.read_noise_V = *log_uniform_or_zero(1e-9, 1.0);
    c.noise.fixed_pattern_rms_V = *log_uniform_or_zero(1e-9, 1.0);
    return c;
  });
}

// Distance inside the unambiguous range c T0 / 2 (or just outside it, one time in 8).
double distance_for(const TofLockinConfig& c, double u) { return u * max_range_m(c.source); }

void check_point(const LockinPoint& p) {
  const double f[] = {p.distance_m, p.delay_s, p.signal_V, p.v1_V,        p.v2_V,  p.n1_e,       p.n2_e,
                      p.mean_m,     p.bias_m,  p.std_m,    p.std_first_m, p.fpn_m, p.accuracy_m, p.snr};
  for (double v : f) RC_ASSERT(finite(v));
  RC_ASSERT(p.std_m >= 0 && p.std_first_m >= 0 && p.fpn_m >= 0 && p.accuracy_m >= 0);
  if (p.detect == LockinDetect::Detectable) RC_ASSERT(p.accuracy_m >= std::fabs(p.bias_m) * (1 - 1e-12));
}

RC_GTEST_PROP(LockinStress, AnyLegalPointIsFinite, ()) {
  const TofLockinConfig cfg = *lockin_config_gen();
  const double s = *log_uniform_or_zero(1e-18, 1.0), b = *log_uniform_or_zero(1e-18, 1.0);
  const double u =
      *rc::gen::weightedOneOf<double>({{7, rc::gen::map(rc::gen::inRange(0, 1001), [](int i) { return i / 1000.0; })},
                                       {1, rc::gen::element(-0.1, 1.5)}});
  const LockinPoint p = evaluate_point(cfg, s, b, distance_for(cfg, u), *rc::gen::element(1LL, 7LL, 100000LL));
  RC_TAG(to_string(p.detect));
  check_point(p);
}

// The detectable points of the space (signal chosen above the detection threshold). The ADC is
// dithered (read noise >= 2 LSB): with sigma << LSB the variance of a code depends on where the
// mean sits inside it (0 mid-code, LSB^2/4 on an edge), so the SNR test of the denominator, and
// with it noise_limited, legitimately comes and goes as the signal grows.
RC_GTEST_PROP(LockinStress, MoreSignalNeverLosesDetection, ()) {
  TofLockinConfig cfg = *lockin_config_gen();
  cfg.noise.read_noise_V = std::min(1.0, std::max(cfg.noise.read_noise_V, 2 * adc_lsb_V(cfg)));
  const double d = distance_for(cfg, *rc::gen::map(rc::gen::inRange(1, 1000), [](int i) { return i / 1000.0; }));
  const double s_thr = signal_current_for_voltage_A(cfg, cfg.readout.detection_threshold_V, d);
  RC_PRE(std::isfinite(s_thr) && s_thr > 0);
  const double s1 = s_thr * *log_uniform(0.5, 1e4), s2 = s1 * *log_uniform(1.0, 1e4);
  const double b = *log_uniform_or_zero(1e-18, 1e-3);
  const LockinPoint p1 = evaluate_point(cfg, s1, b, d, 1), p2 = evaluate_point(cfg, s2, b, d, 1);
  RC_TAG(to_string(p1.detect));
  if (p1.detect == LockinDetect::Detectable && p2.detect != LockinDetect::Saturated)
    RC_ASSERT(p2.detect == LockinDetect::Detectable);
}

// Fine ADC (16 bits, LSB far below the noise): the first-order range noise never falls as the
// background rises (ambient subtracted: the background adds shot noise only).
RC_GTEST_PROP(LockinStress, MoreBackgroundNeverLowersNoise, ()) {
  TofLockinConfig cfg = *lockin_config_gen();
  cfg.readout.adc_bits = 16;
  cfg.readout.ambient_subtraction = true;
  cfg.pixel.fd1_capacitance_F = *log_uniform(1e-14, 1e-9);
  cfg.pixel.fd2_capacitance_F = *log_uniform(1e-14, 1e-9);
  cfg.pixel.saturation_voltage_V = *log_uniform(0.1, 10.0);
  cfg.pixel.offset_voltage_V = 0.3 * cfg.pixel.saturation_voltage_V;
  // The offset charge of 0.3 V_sat is background-independent noise; with it most drawn points
  // fail the preconditions below (rapidcheck gives up), so the property is checked without it.
  cfg.nonideal.offset_shot_noise = false;
  // The range-noise detectability rule off (as `--set readout.max_range_noise_fraction=1e6`):
  // the property is the noise's, and with the rule most drawn points are not detectable.
  cfg.readout.max_range_noise_fraction = 1e6;
  cfg.readout.adc_full_scale_V = 4 * cfg.pixel.source_follower_gain * cfg.pixel.saturation_voltage_V;
  cfg.noise.read_noise_V = 100 * adc_lsb_V(cfg);
  const double d = distance_for(cfg, *rc::gen::map(rc::gen::inRange(1, 1000), [](int i) { return i / 1000.0; }));
  const double s_thr = signal_current_for_voltage_A(cfg, cfg.readout.detection_threshold_V, d);
  RC_PRE(std::isfinite(s_thr) && s_thr > 0);
  const double s = s_thr * *log_uniform(1.0, 1e3), b1 = *log_uniform(1e-18, 1e-3), b2 = b1 * *log_uniform(1.0, 1e7);
  // Away from the ADC's ends (every sample 9 sigma inside the codes): clipping at code 0 or at
  // full scale removes variance, which more background can then legitimately do.
  const double lsb = adc_lsb_V(cfg), top = lsb * (std::ldexp(1.0, cfg.readout.adc_bits) - 1);
  for (double b : {b1, b2}) {
    const FrameCharge ch = frame_charge(cfg, s, b, round_trip_delay_s(d));
    for (int k = 0; k < 2; ++k)
      for (double e : {ch.total_e(k), ch.ambient_e()}) {
        const TapSample t = tap_sample(cfg, k, e);
        RC_PRE(t.mean_V - 9 * t.sigma_V > lsb && t.mean_V + 9 * t.sigma_V < top);
      }
  }
  const LockinPoint p1 = evaluate_point(cfg, s, b1, d, 1), p2 = evaluate_point(cfg, s, b2, d, 1);
  RC_PRE(p1.detect == LockinDetect::Detectable && p2.detect == LockinDetect::Detectable);
  RC_ASSERT(p2.std_first_m >= p1.std_first_m * (1 - 1e-9));
}

}  // namespace
}  // namespace rangesim::golden

namespace rangesim::systemc::lockin {
namespace {

using stress::log_uniform;

// A configuration whose gate edges fall on the gate clock: T0 = k cycles, T_rep = m T0; one pixel.
rc::Gen<TofLockinConfig> kernel_config_gen() {
  return rc::gen::exec([] {
    TofLockinConfig c = *golden::lockin_config_gen();
    const int k = *rc::gen::element(1, 2, 5, 64);
    const int m = *rc::gen::element(2, 4, 10, 1000);
    c.source.duty_cycle = 1.0 / m;
    c.gates.clock_Hz = k / c.source.pulse_width_s;
    c.pixel.rows = c.pixel.columns = 1;
    c.readout.adc_conversion_cycles = 1;
    c.readout.output_cycles_per_row = 1;
    return c;
  });
}

LockinSimOptions aggregated(bool noise, std::uint64_t seed) {
  LockinSimOptions o;
  o.noise = noise;
  o.event_skipping = true;
  o.aggregate = true;
  o.seed = seed;
  return o;
}

RC_GTEST_PROP(LockinKernelStress, NoiseFreeKernelEqualsGolden, ()) {
  const TofLockinConfig cfg = *kernel_config_gen();
  const double s = *stress::log_uniform_or_zero(1e-18, 1.0), b = *stress::log_uniform_or_zero(1e-18, 1.0);
  // Any delay in range, including a pulse whose tail passes T_rep (duty 0.5 with a rise time).
  const double delay =
      cfg.source.pulse_width_s * *rc::gen::map(rc::gen::inRange(0, 1001), [](int i) { return i / 1000.0; });
  TofLockinSensorKernel k(cfg, aggregated(false, 1), 1, 1, {LockinPixelStimulus{s, b, delay}}, 1);
  k.run();
  const golden::FrameCharge ch = golden::frame_charge(cfg, s, b, delay);
  for (int tap = 0; tap < 2; ++tap) {
    const golden::TapSample g = golden::tap_sample(cfg, tap, ch.total_e(tap));
    const double v = k.adc_input_V(0, 0, 0, tap);
    RC_ASSERT(std::isfinite(v));
    const double vg = cfg.pixel.source_follower_gain * std::min(g.fd_swing_V, cfg.pixel.saturation_voltage_V);
    RC_ASSERT(std::fabs(v - vg) <= 1e-9 * std::fabs(vg) + 1e-300);
  }
}

// Duty 0.5 with a rise time: PHASE3 is empty and the received pulse's tail passes T_rep into the
// next period's PHASE1 (FD1). Golden (the frame's pulse train, pulse_timing.h) and the kernel,
// aggregated and period by period, agree noise-free; formerly golden drained the tail and the
// kernel dropped it, which differed by the drain leakage (1 - eps) / 2 of the tail.
RC_GTEST_PROP(LockinKernelStress, PulseTailPastThePeriodAgreesWithGolden, ()) {
  TofLockinConfig cfg = *kernel_config_gen();
  cfg.source.duty_cycle = 0.5;
  cfg.source.rise_time_s = *rc::gen::element(0.1, 0.4, 0.8) * cfg.source.pulse_width_s;
  cfg.gates.accumulations_per_frame = *rc::gen::inRange(1, 13);
  cfg.gates.clock_Hz = *rc::gen::element(1, 2, 5, 64) / cfg.source.pulse_width_s;
  const double s = *stress::log_uniform(1e-15, 1e-6), b = *stress::log_uniform_or_zero(1e-18, 1e-6);
  const double delay =
      cfg.source.pulse_width_s * *rc::gen::map(rc::gen::inRange(0, 1001), [](int i) { return i / 1000.0; });
  const golden::FrameCharge ch = golden::frame_charge(cfg, s, b, delay);
  LockinSimOptions per_period = aggregated(false, 1);
  per_period.aggregate = false;
  for (const LockinSimOptions& o : {aggregated(false, 1), per_period}) {
    TofLockinSensorKernel k(cfg, o, 1, 1, {LockinPixelStimulus{s, b, delay}}, 1);
    k.run();
    for (int tap = 0; tap < 2; ++tap) {
      const golden::TapSample g = golden::tap_sample(cfg, tap, ch.total_e(tap));
      const double vg = cfg.pixel.source_follower_gain * std::min(g.fd_swing_V, cfg.pixel.saturation_voltage_V);
      RC_ASSERT(std::fabs(k.adc_input_V(0, 0, 0, tap) - vg) <= 1e-9 * std::fabs(vg) + 1e-300);
    }
  }
}

RC_GTEST_PROP(LockinKernelStress, NoisyKernelFiniteAndInRange, ()) {
  const TofLockinConfig cfg = *kernel_config_gen();
  const double s = *stress::log_uniform_or_zero(1e-18, 1.0), b = *stress::log_uniform_or_zero(1e-18, 1.0);
  TofLockinSensorKernel k(cfg, aggregated(true, *rc::gen::arbitrary<std::uint32_t>()), 1, 1,
                          {LockinPixelStimulus{s, b, 0.5 * cfg.source.pulse_width_s}}, 2);
  k.run();
  for (long long f = 0; f < 2; ++f)
    for (int tap = 0; tap < 2; ++tap) {
      RC_ASSERT(std::isfinite(k.adc_input_V(f, 0, 0, tap)));
      RC_ASSERT(k.code(f, 0, 0, tap) >= 0 && k.code(f, 0, 0, tap) < (1LL << cfg.readout.adc_bits));
      RC_ASSERT(k.code(f, 0, 0, tap) >= 0);
    }
}

// Hazard: with aggregation one Poisson draw carries N_acc periods. 1 A x 1 ms pulses x 1e9
// accumulations is 6e24 electrons: std::poisson_distribution<long long> overflowed (the FD went
// negative and the pixel read code 0 instead of saturating).
TEST(LockinHazards, HugeAggregatedChargeSaturates) {
  TofLockinConfig cfg;
  cfg.pixel.rows = cfg.pixel.columns = 1;
  cfg.source.pulse_width_s = 1e-3;
  cfg.source.duty_cycle = 0.5;
  cfg.gates.clock_Hz = 1e4;
  cfg.gates.accumulations_per_frame = 1000000000;
  TofLockinSensorKernel k(cfg, aggregated(true, 3), 1, 1, {LockinPixelStimulus{1.0, 1.0, 0.3e-3}}, 1);
  k.run();
  // The read noise is added after the clip (the source follower reads a saturated FD), so a
  // saturated tap reads the top code within 6 sigma of it, never the bottom.
  const double lsb = cfg.readout.adc_full_scale_V / std::ldexp(1.0, cfg.readout.adc_bits);
  const long long top = (1LL << cfg.readout.adc_bits) - 1;
  const long long margin = static_cast<long long>(std::ceil(6 * cfg.noise.read_noise_V / lsb));
  for (int tap = 0; tap < 2; ++tap) {
    EXPECT_TRUE(std::isfinite(k.adc_input_V(0, 0, 0, tap)));
    EXPECT_GE(k.code(0, 0, 0, tap), top - margin) << "tap " << tap;
  }
}

// 95% confidence intervals (n = 40 frames) of the mean tap value a = V1 - V_cal cover golden's
// quantised mean in 182..200 of 200 repetitions (P(X < 182) = 0.2% for Binomial(200, 0.95)).
// Golden takes the shot noise as Gaussian: at ~1e4 electrons per tap the law is that to 1%.
TEST(LockinKernelStress, ConfidenceIntervalsCoverTheMean) {
  TofLockinConfig cfg;
  cfg.pixel.rows = cfg.pixel.columns = 1;
  cfg.readout.ambient_subtraction = false;
  const double s = 2e-10, b = 1e-10, d = 4.0;
  const golden::LockinPoint gp = golden::evaluate_point(cfg, s, b, d, 1);
  ASSERT_EQ(gp.detect, golden::LockinDetect::Detectable);
  // Golden's digitised mean of tap 1, as evaluate_point forms it.
  const golden::FrameCharge ch = golden::frame_charge(cfg, s, b, golden::round_trip_delay_s(d));
  const golden::TapSample ts = golden::tap_sample(cfg, 0, ch.total_e(0));
  const double truth =
      golden::quantised_moments(ts.mean_V, ts.sigma_V, golden::adc_lsb_V(cfg), 1LL << cfg.readout.adc_bits).mean_V -
      cfg.readout.offset_calibration_V;
  const int reps = 200, n = 40;
  const double t975 = 2.0227;  // Student t, 39 degrees of freedom
  int covered = 0;
  for (int r = 0; r < reps; ++r) {
    TofLockinSensorKernel k(cfg, aggregated(true, 1000 + r), 1, 1,
                            {LockinPixelStimulus{s, b, golden::round_trip_delay_s(d)}}, n);
    k.run();
    double sum = 0, sum2 = 0;
    for (int m = 0; m < n; ++m) {
      double a, bb;
      k.tap_values(m, 0, 0, &a, &bb);
      sum += a, sum2 += a * a;
    }
    const double mean = sum / n, sd = std::sqrt(std::max(0.0, (sum2 - n * mean * mean) / (n - 1)));
    covered += std::fabs(mean - truth) <= t975 * sd / std::sqrt(double(n));
  }
  RecordProperty("covered_of_200", covered);
  EXPECT_GE(covered, 182);
}

}  // namespace
}  // namespace rangesim::systemc::lockin
