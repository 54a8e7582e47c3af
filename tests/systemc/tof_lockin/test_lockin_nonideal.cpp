// tof-lockin's non-idealities: golden's closed forms (golden/tof_lockin/nonideal.h) against the
// clock-level kernel fed the non-ideal stimulus (systemc/tof_lockin/nonideal_stimulus.h).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "core/physics.h"
#include "golden/tof_lockin/lockin_point.h"
#include "golden/tof_lockin/nonideal.h"
#include "golden/tof_lockin/pulse_timing.h"
#include "golden/tof_lockin/tap_charge.h"
#include "lockin_sc_test_util.h"
#include "systemc/common/optical_blur.h"
#include "systemc/tof_lockin/nonideal_stimulus.h"

namespace rangesim::systemc::lockin {
namespace {

constexpr double kDistance_m = 2.0;

// A 16-bit ADC keeps the ADC's own truncation (0.37 mV at 12 bits) out of the fixed-pattern spread.
TofLockinConfig fine_adc(std::vector<test::Edit> edits) {
  edits.push_back({"readout", "adc_bits", "16"});
  edits.push_back({"pixel", "rows", "1"});
  return test::edited_config(edits);
}

double signal_A(const TofLockinConfig& cfg, double volts = 0.3) {
  return golden::signal_current_for_voltage_A(cfg, volts, kDistance_m);
}

// Per-pixel range errors of `maps` range maps averaged, one row of `n` pixels of chip `cfg`.
std::vector<double> averaged_errors(const TofLockinConfig& cfg, int n, long long maps, bool noise, double truth_m) {
  std::vector<LockinPixelStimulus> st = test::uniform(n, signal_A(cfg), 1e-11, kDistance_m);
  apply_fixed_pattern(cfg, cfg.nonideal.fixed_pattern.seed, st, 1, n);
  const long long per_map = cfg.readout.ambient_subtraction ? 2 : 1;
  TofLockinSensorKernel k(cfg, LockinSimOptions{noise, true, true, 7}, 1, n, st, maps * per_map);
  k.run();
  std::vector<double> err(static_cast<std::size_t>(n), 0.0);
  for (int c = 0; c < n; ++c) {
    for (long long m = 0; m < k.range_maps(); ++m) err[static_cast<std::size_t>(c)] += k.range_m(m, 0, c);
    err[static_cast<std::size_t>(c)] = err[static_cast<std::size_t>(c)] / static_cast<double>(maps) - truth_m;
  }
  return err;
}

double rms(const std::vector<double>& v) {
  double s = 0;
  for (double x : v) s += x * x;
  return std::sqrt(s / static_cast<double>(v.size()));
}

// The noise-free range of a pixel without fixed pattern: the reference of the spread.
double ideal_range_m(const TofLockinConfig& cfg) {
  TofLockinConfig c = cfg;
  c.nonideal.fixed_pattern = {};
  return kDistance_m + averaged_errors(c, 1, 1, false, kDistance_m)[0];
}

TEST(LockinNonideal, TapMismatchAndPrnuSpreadIsGoldensFixedPattern) {
  // Ambient frame on: PRNU cancels in the ratio, the tap mismatch stays (sqrt 2 K m a b / s^2).
  const TofLockinConfig cfg =
      fine_adc({{"fixed_pattern", "prnu_fraction", "0.02"}, {"fixed_pattern", "tap_mismatch_fraction", "0.01"}});
  const golden::LockinPoint p = golden::evaluate_point(cfg, signal_A(cfg), 1e-11, kDistance_m, 1);
  ASSERT_EQ(p.detect, golden::LockinDetect::Detectable);
  ASSERT_GT(p.fpn_m, 0.01);
  const double spread = rms(averaged_errors(cfg, 3000, 1, false, ideal_range_m(cfg)));
  // 3000 pixels: the rms is known to 1.3 %; the closed form is first order in m = 1 %.
  EXPECT_NEAR(spread / p.fpn_m, 1.0, 0.05) << "kernel " << spread << " golden " << p.fpn_m;
}

TEST(LockinNonideal, DsnuAndPrnuWithoutAmbientFrameAreGoldensFixedPattern) {
  // Without the ambient frame the dark-current spread (1 pA +- 20 %: 310 e- +- 62 e- per FD) and
  // the PRNU of the background stay in the taps.
  const TofLockinConfig cfg = fine_adc({{"readout", "ambient_subtraction", "false"},
                                        {"readout", "offset_calibration_V", "0.02"},
                                        {"fixed_pattern", "prnu_fraction", "0.02"},
                                        {"noise", "dark_current_A", "1e-12"},
                                        {"fixed_pattern", "dsnu_rms_A", "2e-13"}});
  const golden::LockinPoint p = golden::evaluate_point(cfg, signal_A(cfg), 1e-11, kDistance_m, 1);
  ASSERT_EQ(p.detect, golden::LockinDetect::Detectable);
  ASSERT_GT(p.fpn_m, 0.002);
  const double spread = rms(averaged_errors(cfg, 3000, 1, false, ideal_range_m(cfg)));
  EXPECT_NEAR(spread / p.fpn_m, 1.0, 0.06) << "kernel " << spread << " golden " << p.fpn_m;
}

TEST(LockinNonideal, FixedPatternSetsAFloorUnderFrameAveraging) {
  // Over pixels of one chip: the rms error of N averaged maps is sqrt(bias^2 + fpn^2 + var / N)
  // (golden), so it stops falling at fpn; without the fixed pattern it keeps falling as 1/sqrt(N).
  const TofLockinConfig on = fine_adc({{"fixed_pattern", "tap_mismatch_fraction", "0.01"}});
  const TofLockinConfig off = fine_adc({});
  const int n = 600;
  for (long long frames : {1LL, 100LL}) {
    const golden::LockinPoint g_on = golden::evaluate_point(on, signal_A(on), 1e-11, kDistance_m, frames);
    const golden::LockinPoint g_off = golden::evaluate_point(off, signal_A(off), 1e-11, kDistance_m, frames);
    const double mc_on = rms(averaged_errors(on, n, frames, true, kDistance_m));
    const double mc_off = rms(averaged_errors(off, n, frames, true, kDistance_m));
    // 600 pixels: rms to about 3 % (1 sigma); 4 sigma.
    EXPECT_NEAR(mc_on / g_on.accuracy_m, 1.0, 0.12) << frames << " frames: " << mc_on << " vs " << g_on.accuracy_m;
    EXPECT_NEAR(mc_off / g_off.accuracy_m, 1.0, 0.12) << frames << " frames: " << mc_off << " vs " << g_off.accuracy_m;
    if (frames == 100) EXPECT_GT(mc_on, 3 * mc_off) << "the floor";
  }
}

TEST(LockinNonideal, OffsetChargeShotNoiseIsInTheSampleVariance) {
  // A dark pixel's ambient-frame sample: kTC, read and the offset charge's shot noise.
  for (const char* on : {"true", "false"}) {
    const TofLockinConfig cfg = test::edited_config({{"pixel", "rows", "1"}, {"offset_charge", "shot_noise", on}});
    const int n = 4000;
    TofLockinSensorKernel k(cfg, LockinSimOptions{true, true, true, 11}, 1, n, test::uniform(n, 0, 0, 1.0), 2);
    k.run();
    double s = 0, s2 = 0;
    for (int c = 0; c < n; ++c) {
      const double v = k.adc_input_V(1, 0, c, 0);
      s += v, s2 += v * v;
    }
    const double var = s2 / n - (s / n) * (s / n);
    const golden::FrameCharge ch = golden::frame_charge(cfg, 0, 0, 0);
    const double sigma = golden::tap_sample(cfg, 0, ch.ambient_e()).sigma_V;
    // ADC input before the ADC: a Gaussian-like sample; 4000 samples give the variance to 2.2 %.
    EXPECT_NEAR(var / (sigma * sigma), 1.0, 0.09) << "offset shot noise " << on;
  }
}

TEST(LockinNonideal, BlurMakesFlyingPixelsAtADepthStep) {
  // One row, 1 m on the left half and 3 m on the right, the same signal: with a Gaussian PSF of
  // 0.7 px the pixels next to the edge mix both returns and report a range between them,
  // exactly the golden range of the mixed charges.
  TofLockinConfig cfg = fine_adc({{"blur", "psf", "\"gaussian\""}, {"blur", "gaussian_sigma_px", "0.7"}});
  const int n = 20;
  const double I = signal_A(cfg);
  std::vector<LockinPixelStimulus> st;
  for (int c = 0; c < n; ++c) st.push_back({I, 0, golden::round_trip_delay_s(c < n / 2 ? 1.0 : 3.0)});
  std::vector<LockinPixelStimulus> blurred = st;
  apply_blur(cfg, blurred, 1, n);
  TofLockinSensorKernel k(cfg, LockinSimOptions{false, true, true, 1}, 1, n, blurred, 2);
  k.run();
  const std::vector<BlurTap> taps = blur_taps(cfg.nonideal.blur);
  int flying = 0;
  for (int c = 0; c < n; ++c) {
    std::vector<golden::LightReturn> returns;
    for (const BlurTap& t : taps) {
      const LockinPixelStimulus& src = st[static_cast<std::size_t>(blur_source_index(0, c, t, 1, n))];
      returns.push_back({t.w * src.signal_A, src.delay_s});
    }
    const double L = k.range_m(0, 0, c);
    EXPECT_NEAR(L, golden::mixed_range_m(cfg, returns), 2e-3) << "column " << c;
    if (L > 1.2 && L < 2.8) ++flying;
  }
  EXPECT_EQ(flying, 2);  // the two pixels beside the edge
  // Without blur every pixel reports its own surface.
  TofLockinConfig sharp = cfg;
  sharp.nonideal.blur.psf = PsfKind::None;
  std::vector<LockinPixelStimulus> same = st;
  apply_blur(sharp, same, 1, n);
  TofLockinSensorKernel k2(sharp, LockinSimOptions{false, true, true, 1}, 1, n, same, 2);
  k2.run();
  for (int c = 0; c < n; ++c) EXPECT_NEAR(k2.range_m(0, 0, c), c < n / 2 ? 1.0 : 3.0, 2e-3) << "column " << c;
}

TEST(LockinNonideal, MultipathBiasesTheRangeAsGoldenSays) {
  const TofLockinConfig cfg =
      fine_adc({{"multipath", "relative_amplitude", "0.3"}, {"multipath", "extra_path_m", "3.0"}});
  const double I = signal_A(cfg), d = golden::round_trip_delay_s(kDistance_m);
  std::vector<LockinPixelStimulus> st = test::uniform(1, I, 0, kDistance_m);
  add_multipath(cfg, st);
  TofLockinSensorKernel k(cfg, LockinSimOptions{false, true, true, 1}, 1, 1, st, 2);
  k.run();
  const double expected = golden::mixed_range_m(cfg, {{I, d}, {0.3 * I, d + 3.0 / phys::kSpeedOfLight_m_per_s}});
  EXPECT_NEAR(k.range_m(0, 0, 0), expected, 2e-3);
  EXPECT_GT(expected - kDistance_m, 0.2);  // a longer path: the range reads long
  // Golden's evaluation carries the same second return.
  const golden::LockinPoint p = golden::evaluate_point(cfg, I, 0, kDistance_m, 1);
  EXPECT_NEAR(p.mean_m, expected, 0.01);
}

TEST(LockinNonideal, DarkCurrentFollowsTheSensorTemperature) {
  const double at_300 = test::edited_config({}).noise.dark_current_A;
  const TofLockinConfig warm = test::edited_config({{"noise", "temperature_K", "314.0"}});
  EXPECT_NEAR(warm.noise.dark_current_A / at_300, 4.0, 1e-12);  // two doublings of 7 K
}

}  // namespace
}  // namespace rangesim::systemc::lockin
