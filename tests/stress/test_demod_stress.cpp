// Stress and property tests of ls-demodulation (label: stress): the golden chain (front_end,
// decision, evaluation) and the clock-level pixel kernel over extreme but legal inputs.
// Invariants:
//   - no NaN/Inf in the correlator output, the decision or an operating point; probabilities and
//     fractions in [0, 1]; variances >= 0; log of zero or negative currents floored (never NaN);
//   - more beam never lowers the spot-peak output D (aligned reference), so more signal never
//     loses detection below saturation;
//   - the noise-free kernel equals the golden correlator where both are exact (any legal clock
//     schedule), which also checks the aggregation of identical periods against stepping;
//   - correlator.cycles up to 1e9: exact aggregation (hazard: O(N) memory, see below);
//   - 95% confidence intervals of the kernel's mean output cover golden's mean ~95% of the time.
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <iomanip>

#include "golden/ls_demodulation/decision.h"
#include "golden/ls_demodulation/evaluation.h"
#include "golden/ls_demodulation/front_end.h"
#include "stress_gen.h"
#include "stress_print.h"
#include "systemc/ls_demodulation/pixel_kernel.h"
#include "systemc/common/random_stream.h"

namespace rangesim::golden {
namespace {

using stress::log_uniform;
using stress::log_uniform_or_zero;

bool finite(double v) { return std::isfinite(v); }

// A legal configuration with every physical key at an extreme-but-legal value (schema ranges of
// core/ls_demodulation/schema.cpp). Integration 1 ns .. 1 s with N = 1 .. 1e9 periods.
rc::Gen<LsDemodulationConfig> demod_config_gen() {
  return rc::gen::exec([] {
    LsDemodulationConfig c;
    c.pixel.integration_time_s = *log_uniform(1e-9, 1.0);
    const double max_periods = std::min(1e9, c.pixel.integration_time_s * 1e9);  // f0 <= 1e9 Hz
    c.correlator.cycles = static_cast<int>(std::lround(*log_uniform(1.0, std::max(1.0, max_periods))));
    c.modulation.frequency_Hz = c.correlator.cycles / c.pixel.integration_time_s;
    c.pixel.columns = *rc::gen::inRange(1, 33);
    c.modulation.source_duty_cycle = *rc::gen::element(0.5, 0.25, 0.01, 1.0);
    c.correlator.reference_duty_cycle = *rc::gen::element(0.5, 0.25, 0.75, 1.0);
    c.modulation.reference_phase_rad = *rc::gen::element(0.0, 0.0, 1.0, -3.0);
    c.suppression.mirror_gain = *log_uniform(1e-3, 1e3);
    c.suppression.mirror_mismatch = *rc::gen::element(-0.5, -0.01, 0.0, 0.01, 0.5);
    c.suppression.lpf_time_constant_s = *log_uniform(1e-9, 10.0);
    c.log_converter.gain = *log_uniform(1e-3, 100.0);
    c.log_converter.slope_V = *log_uniform(1e-3, 1.0);
    c.log_converter.offset_current_A = *log_uniform(1e-15, 1e-3);
    c.log_converter.leakage_current_A = *log_uniform(1e-24, 1e-6);
    c.correlator.capacitance_plus_F = *log_uniform(1e-18, 1e-9);
    c.correlator.capacitance_minus_F =
        *rc::gen::oneOf(rc::gen::just(c.correlator.capacitance_plus_F), log_uniform(1e-18, 1e-9));
    c.correlator.transconductance_S = *log_uniform(1e-12, 1.0);
    c.correlator.saturation_voltage_V = *log_uniform(1e-3, 10.0);
    c.comparator.threshold_V = *log_uniform(1e-6, 10.0);
    c.comparator.false_activation_max = *log_uniform(1e-12, 1.0);
    c.noise.temperature_K = *log_uniform(1e-3, 500.0);
    c.noise.dark_current_A = *log_uniform_or_zero(1e-18, 1e-9);
    c.noise.read_noise_V = *log_uniform_or_zero(1e-9, 1.0);
    c.noise.fixed_pattern_rms_V = *log_uniform_or_zero(1e-9, 1.0);
    c.spot.fwhm_px = *log_uniform(1e-3, 100.0);
    c.grid.subpixel_points = *rc::gen::inRange(1, 4);
    c.grid.detections = *rc::gen::element(1, 7, 100000);
    c.grid.frames_averaged = *rc::gen::element(1, 3, 100000);
    return c;
  });
}

// Photocurrents over 1e-18 .. 1e-2 A (320 dB).
rc::Gen<double> current_gen() { return log_uniform(1e-18, 1e-2); }

void check_output(const CorrelatorOutput& o) {
  RC_ASSERT(finite(o.diff_V) && finite(o.plus_V) && finite(o.minus_V) && finite(o.peak_abs_V));
  RC_ASSERT(finite(o.shot_var_V2) && o.shot_var_V2 >= 0.0);
  RC_ASSERT(o.clipped_fraction >= 0.0 && o.clipped_fraction <= 1.0 + 1e-12);
  RC_ASSERT(finite(o.lpf_end_A));
  RC_ASSERT(o.peak_abs_V >= std::fabs(o.plus_V) * (1 - 1e-12) && o.peak_abs_V >= std::fabs(o.minus_V) * (1 - 1e-12));
}

RC_GTEST_PROP(DemodStress, CorrelatorFiniteAtAnyLegalPoint, ()) {
  const LsDemodulationConfig cfg = *demod_config_gen();
  const double beam = *rc::gen::weightedOneOf<double>({{1, rc::gen::just(0.0)}, {7, current_gen()}});
  const double bg = *rc::gen::weightedOneOf<double>({{1, rc::gen::just(0.0)}, {7, current_gen()}});
  check_output(correlate_periodic(cfg, pixel_segments(cfg, beam, bg), cfg.correlator.cycles));
}

RC_GTEST_PROP(DemodStress, OperatingPointFiniteAndBounded, ()) {
  LsDemodulationConfig cfg = *demod_config_gen();
  cfg.pixel.columns = std::min(cfg.pixel.columns, 8);  // accuracy cost ~ columns x subpixel points
  const double s = *current_gen(), b = *current_gen();
  const DemodPoint p = evaluate_demod_point(cfg, s, b);
  RC_TAG(to_string(p.detect));
  RC_ASSERT(finite(p.sbr_total_dB) && finite(p.sbr_ratio_dB) && p.sbr_total_dB >= 0.0);
  RC_ASSERT(finite(p.peak_output_V) && finite(p.background_output_V));
  RC_ASSERT(p.row_false_activation >= 0.0 && p.row_false_activation <= 1.0);
  if (p.detect == DemodDetect::Detectable) {
    const DemodAccuracy& a = p.accuracy;
    RC_ASSERT(a.p_detect_min >= 0.0 && a.p_detect_min <= 1.0 + 1e-12);
    RC_ASSERT(a.detected_fraction >= 0.0 && a.detected_fraction <= 1.0);
    if (a.detected_fraction > 0) {  // no position detected at all is an explicit NaN "no result"
      RC_ASSERT(finite(a.accuracy_px) && finite(a.bias_rms_px) && finite(a.noise_std_px) && finite(a.accuracy_m));
      RC_ASSERT(a.accuracy_px >= 0.0 && a.noise_std_px >= 0.0 && a.worst_error_px >= 0.0);
    }
  }
}

// Aligned reference (phase 0, MPY+ over the beam) and an LPF slower than the modulation (tau >=
// 10 periods, what the subtraction is for): D at the spot peak never falls as the beam grows, so
// a detectable signal stays detectable until something saturates. (With tau << 1/f0 the LPF
// follows the beam and a negative mismatch makes D fall with the signal: physics, not rounding.)
RC_GTEST_PROP(DemodStress, MoreSignalNeverLosesDetection, ()) {
  LsDemodulationConfig cfg = *demod_config_gen();
  cfg.modulation.reference_phase_rad = 0;
  cfg.correlator.reference_duty_cycle = cfg.modulation.source_duty_cycle = *rc::gen::element(0.5, 0.25);
  cfg.suppression.lpf_time_constant_s =
      std::min(10.0, std::max(cfg.suppression.lpf_time_constant_s, 10 / cfg.modulation.frequency_Hz));
  // The beam's gain in the MPY+ phase is alpha (1 + eps - duty): at eps = -0.5 and duty 0.5 it
  // is zero and the LPF ripple alone (physics) moves D; keep the gain clear of zero.
  cfg.suppression.mirror_mismatch = *rc::gen::element(-0.01, 0.0, 0.01, 0.5);
  const double b = *current_gen(), s1 = *current_gen(), s2 = s1 * *log_uniform(1.0 + 1e-6, 1e7);
  const Classification c1 = classify(cfg, s1, b), c2 = classify(cfg, s2, b);
  const double d1 = c1.peak.out.diff_V, d2 = c2.peak.out.diff_V;
  // Rounding: D = V+ - V- carries ~1e-15 of the larger swing.
  const double tol = 1e-12 * std::max({std::fabs(c1.peak.out.plus_V), std::fabs(c1.peak.out.minus_V), 1e-300});
  RC_ASSERT(d2 >= d1 - tol);
  if (c1.detect == DemodDetect::Detectable && c2.detect != DemodDetect::Saturated && d2 >= d1)
    RC_ASSERT(c2.detect == DemodDetect::Detectable);
}

// Log of zero or negative current: with the largest negative mismatch and a huge background the
// subtraction drives I_off + I_mod below zero over most of the window; the floor clips it.
RC_GTEST_PROP(DemodStress, NegativeLogArgumentIsFloored, ()) {
  LsDemodulationConfig cfg = *demod_config_gen();
  cfg.suppression.mirror_mismatch = -0.5;
  cfg.suppression.mirror_gain = 1e3;
  const double bg = *log_uniform(1e-6, 1e-2);
  const CorrelatorOutput o = correlate_periodic(cfg, pixel_segments(cfg, 0.0, bg), cfg.correlator.cycles);
  check_output(o);
  if (cfg.log_converter.offset_current_A < 0.5 * 1e3 * bg) RC_ASSERT(o.clipped_fraction > 0.99);
}

// ---- hazard: long accumulations ------------------------------------------------------------
// correlate_periodic stepped every segment of N periods, keeping 3N doubles: N = 1e9 (legal)
// asked for 24 GB. It now aggregates identical periods exactly (O(log N)). Checked against the
// segment-by-segment correlate_stepped at equal start (constant current: same start and same past
// level, so every output must agree to rounding), and for linearity in N up to 1e9.
TEST(DemodHazards, AggregatedPeriodsEqualSteppedPeriods) {
  LsDemodulationConfig cfg;
  cfg.suppression.mirror_mismatch = 0.03;
  cfg.correlator.capacitance_minus_F = 2 * cfg.correlator.capacitance_plus_F;  // D != 0 on a constant current
  for (double tau : {1e-7, 1.2e-3, 10.0})
    for (int n : {1, 2, 3, 37, 1000}) {
      cfg.suppression.lpf_time_constant_s = tau;
      const auto seg = pixel_segments(cfg, 0.0, 3e-10);
      const CorrelatorOutput a = correlate_periodic(cfg, seg, n);
      const CorrelatorOutput b = correlate_stepped(cfg, seg, n, lpf_periodic_start_A(cfg, seg));
      EXPECT_NEAR(a.diff_V, b.diff_V, 1e-12 * std::fabs(b.diff_V)) << tau << " " << n;
      EXPECT_NEAR(a.peak_abs_V, b.peak_abs_V, 1e-12 * b.peak_abs_V) << tau << " " << n;
      EXPECT_NEAR(a.shot_var_V2, b.shot_var_V2, 1e-9 * b.shot_var_V2) << tau << " " << n;
      EXPECT_NEAR(a.clipped_fraction, b.clipped_fraction, 1e-12);
    }
}

// Hazard: correlate_from (transients after a background step) stepped all N x S segments and
// kept their noise kernels: O(N) memory. It now steps only the periods until the LPF transient is
// below rounding and aggregates the rest. Against the fully stepped window, off the periodic
// state (a step of the background, with a beam), for LPFs from 0.3 to 1200 periods.
TEST(DemodHazards, TransientThenAggregatedEqualsStepped) {
  LsDemodulationConfig cfg;
  cfg.suppression.mirror_mismatch = 0.03;
  for (double tau : {3e-6, 1e-4, 1.2e-2})
    for (int n : {1, 7, 400, 3000}) {
      cfg.suppression.lpf_time_constant_s = tau;
      const auto seg = pixel_segments(cfg, 2e-11, 3e-10);
      for (double start : {0.0, 1e-9}) {  // LPF from a dark or a brighter past
        const CorrelatorOutput a = correlate_from(cfg, seg, n, start), b = correlate_stepped(cfg, seg, n, start);
        const double scale = std::max(std::fabs(b.plus_V), std::fabs(b.minus_V));
        EXPECT_NEAR(a.diff_V, b.diff_V, 1e-11 * scale) << tau << " " << n << " " << start;
        EXPECT_NEAR(a.peak_abs_V, b.peak_abs_V, 1e-11 * b.peak_abs_V) << tau << " " << n;
        EXPECT_NEAR(a.shot_var_V2, b.shot_var_V2, 1e-9 * b.shot_var_V2) << tau << " " << n << " " << start;
        EXPECT_NEAR(a.shot_var_plus_V2, b.shot_var_plus_V2, 1e-9 * b.shot_var_V2) << tau << " " << n;
        EXPECT_NEAR(a.lpf_end_A, b.lpf_end_A, 1e-12 * std::fabs(b.lpf_end_A) + 1e-24) << tau << " " << n;
        EXPECT_NEAR(a.clipped_fraction, b.clipped_fraction, 1e-12);
      }
    }
  // N = 1e9 with the preset's 120-period LPF: only the transient (~5000 periods) is stepped.
  cfg.suppression.lpf_time_constant_s = 1.2e-3;
  const auto seg = pixel_segments(cfg, 2e-11, 3e-10);
  const CorrelatorOutput big = correlate_from(cfg, seg, 1000000000, 0.0),
                         per = correlate_periodic(cfg, seg, 1000000000);
  EXPECT_TRUE(std::isfinite(big.shot_var_V2));
  // The transient changes D by a finite amount against a window of 1e9 periods.
  EXPECT_NEAR(big.diff_V, per.diff_V, 1e-4 * std::fabs(per.diff_V));
  EXPECT_NE(big.diff_V, per.diff_V);
}

// Hazard: a piece of the window that starts at the clip point has f = floor there; rounding of
// c0 + c1 e^{-s/tau} gave f <= 0 and the closed form of int ds / f an infinite or NaN value, so
// the shot-noise variance (and the kernel's noisy output) came out NaN. Found by
// DemodKernelStress.NoisyKernelFinite (RC seed 1).
TEST(DemodHazards, ClipPointKeepsShotNoiseFinite) {
  LsDemodulationConfig c;
  c.pixel.integration_time_s = 1, c.correlator.cycles = 1, c.modulation.frequency_Hz = 1;
  c.suppression.mirror_gain = 2.4917441567034042, c.suppression.mirror_mismatch = 0.01;
  c.suppression.lpf_time_constant_s = 1.5446476285619794e-06;
  c.log_converter.gain = 1e-3, c.log_converter.slope_V = 1e-3;
  c.log_converter.offset_current_A = 1.3600307775175289e-14, c.log_converter.leakage_current_A = 1e-24;
  c.correlator.capacitance_plus_F = c.correlator.capacitance_minus_F = 1e-18;
  c.correlator.transconductance_S = 1e-12;
  c.noise.dark_current_A = 1.0121885523191495e-18;
  const double beam = 6.9937693218715311e-09, bg = 8.866845987049414e-08;
  const CorrelatorOutput o = correlate_periodic(c, pixel_segments(c, beam, bg), 1);
  ASSERT_TRUE(std::isfinite(o.shot_var_V2));
  EXPECT_GT(o.clipped_fraction, 0.0);
  // Continuous in the beam: a neighbouring beam whose clip point rounds differently.
  const CorrelatorOutput n = correlate_periodic(c, pixel_segments(c, beam * (1 + 1e-9), bg), 1);
  EXPECT_NEAR(o.shot_var_V2, n.shot_var_V2, 1e-6 * n.shot_var_V2);
}

// Hazard: ln(f / I_off) with f = I_off + alpha eps I next to I_off (a weak signal on the log
// converter's offset current) was computed as log(f / I_off): 1e-24 A on 1e-9 A came out 20%
// wrong (f itself is rounded to ulp(1e-9) = 2e-25). With c0 - I_off passed exactly, log1p.
TEST(DemodHazards, LogOfRatioNearOne) {
  const double ref = 1e-9, d0 = 1e-24, L = 1e-3, tau = 1e-2;
  const LogIntegral li = log_integral(ref + d0, 0.0, tau, L, 1e-15, ref, d0);
  EXPECT_NEAR(li.ln_s, L * 1e-15, 1e-12 * L * 1e-15);
  // And through the chain: D of a constant current is linear in the mismatch at tiny currents.
  LsDemodulationConfig cfg;
  cfg.correlator.capacitance_minus_F = 2 * cfg.correlator.capacitance_plus_F;
  cfg.suppression.mirror_mismatch = 0.01;
  cfg.noise.dark_current_A = 0;
  const double d1 = correlate_periodic(cfg, pixel_segments(cfg, 0.0, 1e-20), 5).diff_V;
  const double d2 = correlate_periodic(cfg, pixel_segments(cfg, 0.0, 2e-20), 5).diff_V;
  EXPECT_NEAR(d2 / d1, 2.0, 1e-6);  // the log's curvature is 1e-13 here
}

// Hazard: Segment held only I_pd = I_dc + I_ac rounded, so under a huge background the beam's
// share and the LPF lag I_avg - I_pd were known to ulp(I_dc) / I_ac (golden and kernel rounded
// the lag differently: 2e-4 of D at background / signal = 1e10). Now I_dc and I_ac are carried
// apart and the LPF as its offset from I_dc. Without mirror mismatch the chain sees only the lag
// (I_mod = alpha (I_pd - I_avg)), so D must not depend on the background at all: exact to rounding.
TEST(DemodHazards, HugeBackgroundKeepsTheBeamShare) {
  LsDemodulationConfig cfg;
  cfg.suppression.mirror_mismatch = 0;
  const double beam = 1e-15;
  const double d0 = correlate_periodic(cfg, pixel_segments(cfg, beam, 0.0), cfg.correlator.cycles).diff_V;
  ASSERT_GT(std::fabs(d0), 0.0);
  for (double ratio : {1e6, 1e8, 1e10}) {
    const double bg = ratio * beam;
    const CorrelatorOutput g = correlate_periodic(cfg, pixel_segments(cfg, beam, bg), cfg.correlator.cycles);
    EXPECT_NEAR(g.diff_V, d0, 1e-12 * std::fabs(d0)) << "background / signal " << ratio;
    // The clock-level kernel: ticking (every cycle a piece), segment by segment, aggregated.
    const systemc::DemodWindowSchedule s = systemc::demod_window_schedule(cfg);
    for (int mode = 0; mode < 3; ++mode) {
      systemc::DemodPixelKernel p(cfg, s);
      pcg32 rng = systemc::pixel_stream(3);
      p.reset(beam, bg, rng, systemc::DemodNoiseSwitches::none(), mode == 2);
      while (!p.window_done()) p.step(mode == 0 ? 1 : p.cycles_to_edge());
      // Ticking sums 100 per-cycle pieces per period: rounding of the quadrature, 1e-9 relative.
      EXPECT_NEAR(p.diff_V(), d0, (mode == 0 ? 1e-9 : 1e-12) * std::fabs(d0))
          << "kernel mode " << mode << ", ratio " << ratio;
    }
  }
}

TEST(DemodHazards, BillionPeriodsAggregateExactly) {
  LsDemodulationConfig cfg;
  cfg.correlator.cycles = 1000000000;
  const auto seg = pixel_segments(cfg, 1e-10, 1e-10);
  const CorrelatorOutput big = correlate_periodic(cfg, seg, cfg.correlator.cycles);
  const CorrelatorOutput small = correlate_periodic(cfg, seg, 1000);
  EXPECT_NEAR(big.diff_V, 1e6 * small.diff_V, 1e-12 * std::fabs(big.diff_V));
  EXPECT_TRUE(std::isfinite(big.shot_var_V2));
  // The LPF's memory spans tau / T0 = 120 periods: past that the variance grows as N.
  EXPECT_NEAR(big.shot_var_V2 / small.shot_var_V2, 1e6, 0.2e6);
}

}  // namespace
}  // namespace rangesim::golden

// ---- clock-level kernel ---------------------------------------------------------------------
namespace rangesim::systemc {
namespace {

using stress::log_uniform;

// A legal configuration whose MPY and beam edges fall on clock edges: P cycles per period,
// duties and phase multiples of 1 / P, N periods.
rc::Gen<LsDemodulationConfig> kernel_config_gen() {
  return rc::gen::exec([] {
    LsDemodulationConfig c = *golden::demod_config_gen();
    const int P = *rc::gen::element(2, 4, 8, 20, 100);
    c.correlator.cycles = *rc::gen::inRange(1, 40);
    c.modulation.frequency_Hz = *log_uniform(1.0, 1e8);
    c.readout.clock_Hz = c.modulation.frequency_Hz * P;
    c.pixel.integration_time_s = c.correlator.cycles / c.modulation.frequency_Hz;
    c.modulation.source_duty_cycle = *rc::gen::inRange(1, P + 1) / double(P);
    c.correlator.reference_duty_cycle = *rc::gen::inRange(1, P + 1) / double(P);
    c.modulation.reference_phase_rad = 2 * M_PI * *rc::gen::inRange(0, P) / double(P);
    return c;
  });
}

RC_GTEST_PROP(DemodKernelStress, NoiseFreeKernelEqualsGolden, ()) {
  const LsDemodulationConfig cfg = *kernel_config_gen();
  DemodWindowSchedule s;
  try {
    s = demod_window_schedule(cfg);
  } catch (const std::invalid_argument&) {
    RC_DISCARD("edges between clock edges after rounding");
  }
  const double beam = *golden::current_gen(), bg = *golden::current_gen();
  const auto g = golden::correlate_periodic(cfg, golden::pixel_segments(cfg, beam, bg), cfg.correlator.cycles);
  // Ticking, event skipping period by period, or the window aggregated (golden's own sums).
  const int mode = *rc::gen::inRange(0, 3);
  const bool tick = mode == 0;
  DemodPixelKernel p(cfg, s);
  pcg32 rng = pixel_stream(7);
  p.reset(beam, bg, rng, DemodNoiseSwitches::none(), mode == 2);
  while (!p.window_done()) p.step(tick ? 1 : p.cycles_to_edge());
  RC_ASSERT(std::isfinite(p.diff_V()) && std::isfinite(p.lpf_A()));
  // Floor of the tolerance: 1e-12 of the swing the whole photocurrent would give on one side
  // (a beam switched fully on for the window, e.g. source duty 1, leaves D = 0 + rounding).
  const auto& lg = cfg.log_converter;
  const double full =
      cfg.correlator.transconductance_S * lg.gain * lg.slope_V /
      std::min(cfg.correlator.capacitance_plus_F, cfg.correlator.capacitance_minus_F) * cfg.pixel.integration_time_s *
      std::log1p(cfg.suppression.mirror_gain * (beam + bg + cfg.noise.dark_current_A) / lg.offset_current_A);
  const double scale = std::max({std::fabs(g.plus_V), std::fabs(g.minus_V), 1e-4 * full});
  // Ticks split a segment into pieces integrated separately: the same exact solution, summed in
  // another order and with other quadrature panels (before the panel fix a fast LPF put the two
  // 100% apart).
  // The log stage amplifies the last bit of the LPF state (golden starts every period from the
  // closed-form periodic state, the kernel carries its own) by kappa = alpha I / I_off, up to 1e9
  // here.
  const double kappa = 1 + cfg.suppression.mirror_gain * (beam + bg + cfg.noise.dark_current_A) / lg.offset_current_A;
  // No background term: Segment carries I_ac beside I_pd and the LPF is held as its offset from
  // I_dc, so the lag I_avg - I_pd is exact to ulp(I_ac) (before, ulp(I_dc) / I_ac: up to 2e-4 of D
  // at background / signal = 1e10; DemodHazards.HugeBackgroundKeepsTheBeamShare).
  const double tol = std::min(1.0, std::max(1e-7, 1e-15 * kappa)) * scale;
  RC_ASSERT(std::fabs(p.plus_V() - g.plus_V) <= tol);
  RC_ASSERT(std::fabs(p.minus_V() - g.minus_V) <= tol);
}

RC_GTEST_PROP(DemodKernelStress, NoisyKernelFinite, ()) {
  const LsDemodulationConfig cfg = *kernel_config_gen();
  DemodWindowSchedule s;
  try {
    s = demod_window_schedule(cfg);
  } catch (const std::invalid_argument&) {
    RC_DISCARD("edges between clock edges after rounding");
  }
  const double beam = *golden::current_gen(), bg = *golden::current_gen();
  RC_LOG() << std::setprecision(17) << "beam_A=" << beam << " background_A=" << bg << "\n";
  DemodPixelKernel p(cfg, s);
  pcg32 rng = pixel_stream(*rc::gen::arbitrary<std::uint32_t>());
  p.reset(beam, bg, rng, DemodNoiseSwitches{});
  while (!p.window_done()) p.step(p.cycles_to_edge());
  RC_ASSERT(std::isfinite(p.plus_V()) && std::isfinite(p.minus_V()));
}

// 95% confidence intervals of the mean of D from n = 40 noisy windows cover golden's noise-free
// mean in 95% of 200 repetitions (independent seeds). The shot noise is Gaussian and exactly
// golden's variance, and the mean of D is golden's (noise is zero-mean), so the coverage is
// Student-t exact: accept 182..200 (P(X < 182) = 0.2% for Binomial(200, 0.95)).
TEST(DemodKernelStress, ConfidenceIntervalsCoverTheMean) {
  LsDemodulationConfig cfg;
  cfg.pixel.integration_time_s = 5e-5;
  cfg.noise.read_noise_V = 0;  // frame-common: drawn by the sensor kernel, not here
  const DemodWindowSchedule s = demod_window_schedule(cfg);
  const double beam = 2e-11, bg = 1e-10;
  const double truth =
      golden::correlate_periodic(cfg, golden::pixel_segments(cfg, beam, bg), cfg.correlator.cycles).diff_V;
  const int reps = 200, n = 40;
  const double t975 = 2.0227;  // Student t, 39 degrees of freedom
  int covered = 0;
  for (int r = 0; r < reps; ++r) {
    double sum = 0, sum2 = 0;
    for (int i = 0; i < n; ++i) {
      DemodPixelKernel p(cfg, s);
      pcg32 rng = pixel_stream(pixel_stream_key(0xC1, static_cast<std::uint64_t>(r), 0, static_cast<std::uint32_t>(i)));
      p.reset(beam, bg, rng, DemodNoiseSwitches{});
      while (!p.window_done()) p.step(p.cycles_to_edge());
      sum += p.diff_V(), sum2 += p.diff_V() * p.diff_V();
    }
    const double mean = sum / n, sd = std::sqrt(std::max(0.0, (sum2 - n * mean * mean) / (n - 1)));
    covered += std::fabs(mean - truth) <= t975 * sd / std::sqrt(double(n));
  }
  RecordProperty("covered_of_200", covered);
  EXPECT_GE(covered, 182);
  EXPECT_LE(covered, 200);
}

}  // namespace
}  // namespace rangesim::systemc
