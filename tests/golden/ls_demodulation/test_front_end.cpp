// Front end of the demodulating pixel: exact LPF/integrator solution against brute-force time
// stepping, log integral, selectivity and step settling in closed form.
#include <gtest/gtest.h>

#include <cmath>

#include "golden/ls_demodulation/front_end.h"
#include "golden/ls_demodulation/selectivity.h"
#include "test_helpers_demod.h"

namespace rangesim::golden {
namespace {

// Brute-force chain with tiny time steps (midpoint rule, LPF by its exact step): what the exact
// solution must agree with.
double stepped_diff_V(const LsDemodulationConfig& cfg, const std::vector<Segment>& period, int periods, double start_A,
                      int steps_per_segment) {
  const auto& s = cfg.suppression;
  const auto& lg = cfg.log_converter;
  const double gain = cfg.correlator.transconductance_S * lg.gain * lg.slope_V;
  double Iavg = start_A, plus = 0, minus = 0;
  for (int p = 0; p < periods; ++p)
    for (const Segment& seg : period) {
      const double dt = seg.duration_s / steps_per_segment, I = seg.photocurrent_A;
      for (int i = 0; i < steps_per_segment; ++i) {
        const double mid = I + (Iavg - I) * std::exp(-0.5 * dt / s.lpf_time_constant_s);
        const double Ilog = lg.offset_current_A + s.mirror_gain * (1 + s.mirror_mismatch) * I - s.mirror_gain * mid;
        const double v = std::log(std::max(Ilog, lg.leakage_current_A) / lg.offset_current_A);
        (seg.branch > 0 ? plus : minus) +=
            gain / (seg.branch > 0 ? cfg.correlator.capacitance_plus_F : cfg.correlator.capacitance_minus_F) * v * dt;
        Iavg = I + (Iavg - I) * std::exp(-dt / s.lpf_time_constant_s);
      }
    }
  return plus - minus;
}

TEST(DemodFrontEnd, LogIntegralMatchesFineMidpoint) {
  const double tau = 1.2e-3, L = 5e-6, floor = 1e-15, ref = 1e-9;
  struct Case {
    double c0, c1;
  };
  // Unclipped, rising; clipped at the start and recovering; clipped at the end.
  for (const Case c : {Case{1e-9, 5e-10}, Case{1e-9, -1.5e-9}, Case{-2e-13, 2.1e-13}, Case{1e-9, -1.00001e-9}}) {
    const LogIntegral li = log_integral(c.c0, c.c1, tau, L, floor, ref);
    const int n = 200000;
    double ln = 0;
    for (int i = 0; i < n; ++i) {
      const double t = (i + 0.5) * L / n;
      ln += std::log(std::max(c.c0 + c.c1 * std::exp(-t / tau), floor) / ref) * L / n;
    }
    EXPECT_NEAR(li.ln_s, ln, 1e-6 * std::fabs(ln) + 1e-14) << c.c0 << " " << c.c1;
  }
}

TEST(DemodFrontEnd, PeriodicSteadyStateRepeats) {
  const LsDemodulationConfig cfg = test::demod_cfg();
  const auto seg = pixel_segments(cfg, 3e-10, 1e-9);
  const double x = lpf_periodic_start_A(cfg, seg);
  const CorrelatorOutput one = correlate_from(cfg, seg, 1, x);
  EXPECT_NEAR(one.lpf_end_A, x, 1e-12 * x);  // the LPF returns to its start after a period
  EXPECT_NEAR(x, 1e-9 + cfg.noise.dark_current_A + 0.5 * 3e-10, 2e-3 * x);  // ~ mean I_pd (eq. 2.9)
}

TEST(DemodFrontEnd, ExactSolutionMatchesTimeStepping) {
  LsDemodulationConfig cfg = test::demod_cfg();
  cfg.modulation.reference_phase_rad = 0.7;   // four segments per period
  for (double beam : {2e-11, 5e-10, 3e-9}) {  // linear, compressed, clipped negative half-periods
    const auto seg = pixel_segments(cfg, beam, 2e-10);
    const double start = lpf_periodic_start_A(cfg, seg) * 0.9;  // off steady state: transient too
    const double exact = correlate_from(cfg, seg, cfg.correlator.cycles, start).diff_V;
    const double stepped = stepped_diff_V(cfg, seg, cfg.correlator.cycles, start, 20000);
    EXPECT_NEAR(exact, stepped, 1e-5 * std::fabs(stepped) + 1e-9) << beam;
  }
}

TEST(DemodFrontEnd, ConstantBackgroundIsRejected) {
  LsDemodulationConfig cfg = test::demod_cfg();
  for (double eps : {0.0, 0.01, -0.003}) {
    cfg.suppression.mirror_mismatch = eps;
    for (double b : {1e-12, 1e-9, 1e-7}) {
      const CorrelatorOutput o = correlate_periodic(cfg, pixel_segments(cfg, 0.0, b), cfg.correlator.cycles);
      EXPECT_NEAR(o.diff_V, 0.0, 1e-12) << eps << " " << b;  // 50% duty, C1 = C2: DC cancels
    }
  }
  // Mismatch alone: the residue alpha eps I_dc drives both integrators together (common mode).
  cfg.suppression.mirror_mismatch = 0.01;
  const CorrelatorOutput o = correlate_periodic(cfg, pixel_segments(cfg, 0.0, 1e-6), cfg.correlator.cycles);
  EXPECT_GT(o.peak_abs_V, cfg.correlator.saturation_voltage_V);
}

TEST(DemodFrontEnd, SmallSignalGainIsLinearCorrelation) {
  // alpha (1 + eps) I_s / 2 swing (the LPF passes nothing at f0), beta s / I_off log gain, g_m T / C integration: D =
  // g_m beta s alpha I_s T / (2 C I_off).
  const LsDemodulationConfig cfg = test::demod_cfg();
  const double Is = 1e-13;
  const double D = correlate_periodic(cfg, pixel_segments(cfg, Is, 1e-13), cfg.correlator.cycles).diff_V;
  const double expect = cfg.correlator.transconductance_S * cfg.log_converter.slope_V * cfg.suppression.mirror_gain *
                        (1 + cfg.suppression.mirror_mismatch) * Is * cfg.pixel.integration_time_s /
                        (2 * cfg.correlator.capacitance_plus_F * cfg.log_converter.offset_current_A);
  EXPECT_NEAR(D, expect, 2e-3 * expect);
}

TEST(DemodSelectivity, EvenHarmonicsRejectedAtHalfDuty) {
  const LsDemodulationConfig cfg = test::demod_cfg();
  EXPECT_EQ(harmonic_selectivity_dB(cfg, 1e-10, 1), 0.0);
  EXPECT_TRUE(std::isinf(harmonic_selectivity_dB(cfg, 1e-10, 2)));
  EXPECT_TRUE(std::isinf(harmonic_selectivity_dB(cfg, 1e-10, 4)));
  EXPECT_NEAR(harmonic_selectivity_dB(cfg, 1e-10, 3), 20 * std::log10(1.0 / 3), 0.01);  // square reference: 1/k
  // The exact nonlinear chain with a small square background agrees.
  // (numerical floor: D is the difference of two integrator swings each ~1e9 times larger)
  EXPECT_LT(harmonic_selectivity_square_dB(cfg, 1e-10, 1e-12, 2), -150.0);
  EXPECT_NEAR(harmonic_selectivity_square_dB(cfg, 1e-10, 1e-12, 3), 20 * std::log10(1.0 / 3), 0.1);
}

TEST(DemodSelectivity, DutyExplainsMinus13dB) {
  LsDemodulationConfig cfg = test::demod_cfg();
  cfg.correlator.reference_duty_cycle = duty_for_even_harmonic_dB(-13.0);
  EXPECT_NEAR(cfg.correlator.reference_duty_cycle, 0.4281, 1e-4);
  EXPECT_NEAR(harmonic_selectivity_dB(cfg, 1e-10, 2), -13.0, 1e-4);  // LPF leak |H_2| / |H_1| - 1 ~ 1e-6
  // Capacitor mismatch adds no even-harmonic response (only DC).
  LsDemodulationConfig c2 = test::demod_cfg();
  c2.correlator.capacitance_minus_F *= 1.05;
  EXPECT_TRUE(std::isinf(harmonic_selectivity_dB(c2, 1e-10, 2)));
}

TEST(DemodSelectivity, StepSettling) {
  const LsDemodulationConfig cfg = test::demod_cfg();
  EXPECT_NEAR(step_settling_time_s(cfg, 0.01), 1.2e-3 * std::log(100.0), 1e-12);
  EXPECT_NEAR(step_residual_fraction(cfg, 1.2e-3), std::exp(-1.0), 1e-15);
  // Correlator error after a x10 background step decays with the LPF.
  const double e0 = std::fabs(step_correlator_error_V(cfg, 1e-10, 1e-9, 0));
  const double e1 = std::fabs(step_correlator_error_V(cfg, 1e-10, 1e-9, 5 * 1.2e-3));
  EXPECT_GT(e0, 0);
  EXPECT_LT(e1, 0.02 * e0);
}

}  // namespace
}  // namespace rangesim::golden
