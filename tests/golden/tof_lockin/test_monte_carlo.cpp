// Monte Carlo check of the closed-form mean and variance of L (lockin_point.h): 20000 frames of
// the same model, drawn electron by electron (Poisson, the offset charge too) with Gaussian kTC and read noise, the
// truncating ADC of eq. 4.9, the ambient frame and eq. 2.25. Seeded, so the test is deterministic.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "golden/tof_lockin/lockin_point.h"
#include "golden/tof_lockin/pulse_timing.h"
#include "golden/tof_lockin/range_estimate.h"
#include "golden/tof_lockin/tap_charge.h"
#include "lockin_test_util.h"

namespace rangesim::golden {

namespace {

struct McResult {
  double mean = 0, var = 0, se_mean = 0, se_var = 0;
};

// Frames that give no range (the kernel's rule: a + b > 0 and >= detection_threshold_V) are left
// out when `only_ranges`, as a range map or a Monte Carlo of the kernels does; `kept` counts the rest.
McResult monte_carlo(const TofLockinConfig& cfg, double is, double ib, double L, int frames, unsigned seed,
                     bool only_ranges = false, int* kept = nullptr) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> gauss(0.0, 1.0);
  const FrameCharge c = frame_charge(cfg, is, ib, round_trip_delay_s(L));
  const double lsb = adc_lsb_V(cfg), top = std::ldexp(1.0, cfg.readout.adc_bits) - 1;
  const double K = max_range_m(cfg.source);
  // One readout of tap k holding `mean_e` electrons on average: Poisson electrons, frozen kTC
  // of the reset, read noise, truncating ADC.
  // The offset charge C V_offset / q is Poisson too when its shot noise is on: drawn with the rest.
  const auto read = [&](int k, double mean_e) {
    const double g = volts_per_electron(cfg, k);
    const double n_off =
        cfg.nonideal.offset_shot_noise ? cfg.pixel.source_follower_gain * cfg.pixel.offset_voltage_V / g : 0.0;
    std::poisson_distribution<long long> pois(mean_e + n_off);
    const double v = g * (static_cast<double>(pois(rng)) - n_off) +
                     cfg.pixel.source_follower_gain * cfg.pixel.offset_voltage_V + ktc_noise_V(cfg, k) * gauss(rng) +
                     cfg.noise.read_noise_V * gauss(rng);
    return std::clamp(std::floor(v / lsb), 0.0, top) * lsb;
  };
  double s1 = 0, s2 = 0, s4 = 0;
  std::vector<double> ls;
  for (int f = 0; f < frames; ++f) {
    double t[2];
    for (int k = 0; k < 2; ++k) {
      t[k] = read(k, c.total_e(k)) - cfg.readout.offset_calibration_V;
      if (cfg.readout.ambient_subtraction) t[k] -= read(k, c.ambient_e());
    }
    const double s = t[0] + t[1];
    if (only_ranges && (!(s > 0) || s < cfg.readout.detection_threshold_V * (1 - 1e-9))) continue;
    ls.push_back(K * t[1] / s);
    s1 += ls.back();
  }
  const double n = static_cast<double>(ls.size());
  if (kept) *kept = static_cast<int>(ls.size());
  McResult r;
  r.mean = s1 / n;
  for (double l : ls) s2 += (l - r.mean) * (l - r.mean), s4 += std::pow(l - r.mean, 4);
  r.var = s2 / (n - 1);
  r.se_mean = std::sqrt(r.var / n);
  r.se_var = std::sqrt((s4 / n - r.var * r.var) / n);  // no normality assumed
  return r;
}

void expect_matches(const TofLockinConfig& cfg, double is, double ib, double L, unsigned seed) {
  const LockinPoint p = evaluate_point(cfg, is, ib, L, 1);
  ASSERT_EQ(p.detect, LockinDetect::Detectable);
  const McResult mc = monte_carlo(cfg, is, ib, L, 20000, seed);
  EXPECT_NEAR(p.mean_m, mc.mean, 5 * mc.se_mean) << "bias " << p.bias_m << " snr " << p.snr;
  EXPECT_NEAR(p.std_m * p.std_m, mc.var, 5 * mc.se_var) << "std " << p.std_m << " mc " << std::sqrt(mc.var);
}

}  // namespace

TEST(LockinMonteCarlo, PresetMidSignalWithBackground) {
  // 0.3 nA signal (0.15 V), 0.1 nA background (about 3100 e- per tap), 2 m: ambient frame on.
  expect_matches(test::lockin_config(), 3e-10, 1e-10, 2.0, 12345u);
}

// The range-noise bound off (readout.max_range_noise_fraction), so that golden's moments can be
// checked where the ratio is far from linear.
TofLockinConfig unbounded_config() {
  TofLockinConfig cfg = test::lockin_config();
  cfg.readout.max_range_noise_fraction = 1e6;
  return cfg;
}

TEST(LockinMonteCarlo, PresetWeakSignalFarTarget) {
  // 0.03 nA (15 mV, ~940 e-): SNR ~ 7, where the second-order terms of the delta method count.
  expect_matches(unbounded_config(), 3e-11, 1e-12, 9.0, 777u);
}

// SNR ~ 3.6 of a + b at 0.012 nA, 1 m: the detection threshold (5 mV) cuts into the frames and the
// ratio is far from linear. Golden integrates the moments over the frames that give a range; the
// Monte Carlo keeps the same frames. The delta method's variance, which golden used before, is
// outside the same test: the check has the power to see the difference.
TEST(LockinMonteCarlo, LowSnrMomentsOverTheFramesThatGiveARange) {
  const TofLockinConfig cfg = unbounded_config();
  const double is = 1.2e-11, ib = 1e-14, L = 1.0;
  const LockinPoint p = evaluate_point(cfg, is, ib, L, 1);
  ASSERT_EQ(p.detect, LockinDetect::Detectable);
  EXPECT_LT(p.snr, 4.0);
  int kept = 0;
  const McResult mc = monte_carlo(cfg, is, ib, L, 40000, 4711u, true, &kept);
  EXPECT_LT(kept, 39000);  // the threshold removes a visible share of the frames
  EXPECT_NEAR(p.mean_m, mc.mean, 5 * mc.se_mean);
  EXPECT_NEAR(p.std_m * p.std_m, mc.var, 5 * mc.se_var) << "std " << p.std_m << " mc " << std::sqrt(mc.var);
  // What the second-order delta method gives at the same point (range_moments), 5 SE away or more.
  const double lsb = adc_lsb_V(cfg);
  const FrameCharge c = frame_charge(cfg, is, ib, round_trip_delay_s(L));
  double mu[2], var[2];
  for (int k = 0; k < 2; ++k) {
    const TapSample on = tap_sample(cfg, k, c.total_e(k)), off = tap_sample(cfg, k, c.ambient_e());
    mu[k] = on.mean_V - off.mean_V;
    var[k] = on.sigma_V * on.sigma_V + off.sigma_V * off.sigma_V + lsb * lsb / 6;
  }
  const RangeMoments delta = range_moments(max_range_m(cfg.source), mu[0], var[0], mu[1], var[1]);
  EXPECT_GT(std::fabs(delta.var_m2 - mc.var), 5 * mc.se_var) << "delta " << std::sqrt(delta.var_m2);
}

TEST(LockinMonteCarlo, NonIdealPixelWithoutAmbientFrame) {
  // Deep electrons, leaky drain, no ambient frame and a mis-calibrated offset: the bias terms.
  TofLockinConfig cfg = test::lockin_config();
  cfg.pixel.charge_separation = 0.9;
  cfg.pixel.drain_efficiency = 0.98;
  cfg.readout.ambient_subtraction = false;
  cfg.readout.offset_calibration_V = 0.015;
  cfg.source.rise_time_s = 8e-9;
  const LockinPoint p = evaluate_point(cfg, 2e-10, 2e-11, 5.0, 1);
  EXPECT_GT(std::fabs(p.bias_m), 3 * p.std_m / std::sqrt(20000.0));  // the bias is resolved by the check
  expect_matches(cfg, 2e-10, 2e-11, 5.0, 4242u);
}

}  // namespace rangesim::golden
