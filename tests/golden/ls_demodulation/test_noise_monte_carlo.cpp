// Monte Carlo check (seeded) of the closed-form shot noise at the correlator output: photo-
// electrons drawn per 25 ns bin (Poisson), pushed through the full nonlinear chain (exact LPF step,
// subtraction, clipped log, integrators); the sample mean and variance of V_out+ - V_out- must
// match correlate_periodic's diff_V and shot_var_V2 within 5 standard errors. The mean carries
// the log's Jensen bias from the per-bin fluctuation (an artefact of an infinite-bandwidth log
// fed with binned shot noise), added to the expectation to second order.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "core/physics.h"
#include "golden/ls_demodulation/front_end.h"
#include "test_helpers_demod.h"

namespace rangesim::golden {
namespace {

struct Stats {
  double mean = 0, var = 0;
  double jensen_V = 0;  // second-order bias of E[ln] from the per-bin fluctuation (binning artefact)
};

Stats simulate(const LsDemodulationConfig& cfg, double beam_A, double background_A, int trials, uint64_t seed) {
  const auto period = pixel_segments(cfg, beam_A, background_A);
  const auto& s = cfg.suppression;
  const auto& lg = cfg.log_converter;
  const double q = phys::kElementaryCharge_C, tau = s.lpf_time_constant_s;
  const double gain = cfg.correlator.transconductance_S * lg.gain * lg.slope_V;
  const double x = lpf_periodic_start_A(cfg, period);
  double mean_I = 0, T0 = 0;
  for (const auto& seg : period) mean_I += seg.photocurrent_A * seg.duration_s, T0 += seg.duration_s;
  mean_I /= T0;
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> lpf_noise(0.0, std::sqrt(q * mean_I / (2 * tau)));  // LPF state before the window
  double sum = 0, sum2 = 0, jensen = 0, Inf = x;
  for (int t = 0; t < trials; ++t) {
    double Iavg = x + lpf_noise(rng), plus = 0, minus = 0;
    Inf = x;
    for (int p = 0; p < cfg.correlator.cycles; ++p)
      for (const auto& seg : period) {
        const int bins = std::max(1, static_cast<int>(std::lround(seg.duration_s / 25e-9)));
        const double dt = seg.duration_s / bins;
        std::poisson_distribution<long> pois(seg.photocurrent_A * dt / q);
        const double C = seg.branch > 0 ? cfg.correlator.capacitance_plus_F : cfg.correlator.capacitance_minus_F;
        for (int i = 0; i < bins; ++i) {
          const double I = pois(rng) * q / dt;
          const double mid = I + (Iavg - I) * std::exp(-0.5 * dt / tau);
          const double Ilog = lg.offset_current_A + s.mirror_gain * (1 + s.mirror_mismatch) * I - s.mirror_gain * mid;
          const double v = gain / C * std::log(std::max(Ilog, lg.leakage_current_A) / lg.offset_current_A) * dt;
          (seg.branch > 0 ? plus : minus) += v;
          if (t == 0) {  // E[ln(m + e)] ~ ln m - var / (2 m^2), var of alpha (1+eps) I over a bin
            const double I0 = seg.photocurrent_A, mid0 = I0 + (Inf - I0) * std::exp(-0.5 * dt / tau);
            const double m = lg.offset_current_A + s.mirror_gain * (1 + s.mirror_mismatch) * I0 - s.mirror_gain * mid0;
            const double a = s.mirror_gain * (1 + s.mirror_mismatch);
            jensen -= seg.branch * gain / C * dt * a * a * q * I0 / dt / (2 * m * m);
            Inf = I0 + (Inf - I0) * std::exp(-dt / tau);
          }
          Iavg = I + (Iavg - I) * std::exp(-dt / tau);
        }
      }
    const double d = plus - minus;
    sum += d;
    sum2 += d * d;
  }
  Stats st;
  st.mean = sum / trials;
  st.var = (sum2 - trials * st.mean * st.mean) / (trials - 1);
  st.jensen_V = jensen;
  return st;
}

void check(double beam_A, double background_A, uint64_t seed) {
  const LsDemodulationConfig cfg = test::demod_cfg();
  const CorrelatorOutput o = correlate_periodic(cfg, pixel_segments(cfg, beam_A, background_A), cfg.correlator.cycles);
  const int n = 3000;
  const Stats st = simulate(cfg, beam_A, background_A, n, seed);
  const double se_mean = std::sqrt(o.shot_var_V2 / n), se_var = o.shot_var_V2 * std::sqrt(2.0 / (n - 1));
  EXPECT_NEAR(st.mean, o.diff_V + st.jensen_V, 5 * se_mean) << "beam " << beam_A << " background " << background_A;
  EXPECT_NEAR(st.var, o.shot_var_V2, 5 * se_var) << "beam " << beam_A << " background " << background_A;
}

TEST(DemodMonteCarlo, SignalAndBackground) { check(1e-10, 1e-10, 12345); }
TEST(DemodMonteCarlo, StrongBackgroundOnly) { check(0.0, 1e-9, 67890); }

}  // namespace
}  // namespace rangesim::golden
