// A tof-lockin range map's validity (golden/tof_lockin/validity.h, TofLockinSensorKernel::range_valid)
// against golden's detectability on uniform scenes, and what it keeps on a dim one: each range
// value is valid when the noise its own taps imply (first-order delta method) is within
// readout.max_range_noise_fraction x c T0 / 2 (and its SNR reaches readout.min_snr).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "golden/tof_lockin/lockin_point.h"
#include "lockin_sc_test_util.h"

namespace rangesim::systemc::lockin {
namespace {

constexpr double kBackground_A = 20e-12, kDistance_m = 7.5;

double bound_m(const TofLockinConfig& cfg) {
  return cfg.readout.max_range_noise_fraction * golden::max_range_m(cfg.source);
}

// The signal whose golden first-order range noise is `ratio` x the bound (bisection).
double signal_at_noise_ratio(const TofLockinConfig& cfg, double ratio) {
  double lo = 1e-12, hi = 1.5e-9;  // noisier at lo (below the threshold no noise is computed)
  for (int i = 0; i < 80; ++i) {
    const double mid = std::sqrt(lo * hi);
    const golden::LockinPoint p = golden::evaluate_point(cfg, mid, kBackground_A, kDistance_m, 1);
    (p.detect == golden::LockinDetect::BelowThreshold || p.std_first_m > ratio * bound_m(cfg) ? lo : hi) = mid;
  }
  return hi;
}

struct MapStats {
  long long values = 0, valid = 0;
  double valid_ms_m2 = 0, all_ms_m2 = 0, all_max_m = 0;  // errors: valid values, every range value
  double valid_fraction() const { return static_cast<double>(valid) / static_cast<double>(values); }
  double valid_rms_m() const { return std::sqrt(valid_ms_m2 / static_cast<double>(valid)); }
  double all_rms_m() const { return std::sqrt(all_ms_m2 / static_cast<double>(values)); }
};

// One row of 256 identical pixels, 20 range maps (LED + ambient frame each), aggregated.
MapStats run_map(const TofLockinConfig& cfg, double signal_A, std::uint64_t seed) {
  LockinSimOptions o;
  o.aggregate = true, o.seed = seed;
  const int columns = 256;
  TofLockinSensorKernel k(cfg, o, 1, columns, test::uniform(columns, signal_A, kBackground_A, kDistance_m), 40);
  k.run();
  MapStats s;
  for (long long m = 0; m < k.range_maps(); ++m)
    for (int c = 0; c < columns; ++c) {
      const double L = k.range_m(m, 0, c);
      if (!std::isfinite(L)) continue;
      const double e = L - kDistance_m;
      ++s.values, s.all_ms_m2 += e * e, s.all_max_m = std::max(s.all_max_m, std::fabs(e));
      if (k.range_valid(m, 0, c)) ++s.valid, s.valid_ms_m2 += e * e;
    }
  return s;
}

TEST(LockinMapValidity, AgreesWithGoldenOnUniformScenes) {
  const TofLockinConfig cfg = test::edited_config({{"pixel", "rows", "1"}});
  // Golden's noise at 0.8 x the bound: detectable, and nearly every value of the map valid.
  const double inside = signal_at_noise_ratio(cfg, 0.8);
  EXPECT_EQ(golden::evaluate_point(cfg, inside, kBackground_A, kDistance_m, 1).detect,
            golden::LockinDetect::Detectable);
  EXPECT_GT(run_map(cfg, inside, 3).valid_fraction(), 0.95);
  // At 1.25 x the bound: range_error_unbounded, and nearly no value valid.
  const double outside = signal_at_noise_ratio(cfg, 1.25);
  EXPECT_EQ(golden::evaluate_point(cfg, outside, kBackground_A, kDistance_m, 1).detect,
            golden::LockinDetect::RangeErrorUnbounded);
  EXPECT_LT(run_map(cfg, outside, 4).valid_fraction(), 0.05);
  // At the bound itself the two meet: about half the values valid.
  const double f = run_map(cfg, signal_at_noise_ratio(cfg, 1.0), 5).valid_fraction();
  EXPECT_GT(f, 0.3);
  EXPECT_LT(f, 0.7);
}

// A dim wall (golden noise 1.15 x the bound, SNR ~ 9): the SNR-3 rule alone (the bound switched
// off) keeps every value, with an rms error above the bound and metre errors among them; the
// range-noise rule keeps the values whose own taps vouch for them, and their rms error is within it.
TEST(LockinMapValidity, ValidValuesWithinTheBoundOnADimScene) {
  TofLockinConfig cfg = test::edited_config({{"pixel", "rows", "1"}});
  const double dim = signal_at_noise_ratio(cfg, 1.15);
  TofLockinConfig old_rule = cfg;
  old_rule.readout.max_range_noise_fraction = 1e6;
  const MapStats before = run_map(old_rule, dim, 6), after = run_map(cfg, dim, 6);
  std::printf(
      "dim wall %.4g A at %.1f m: SNR-3 rule %lld of %lld valid, rms %.3f m, max %.2f m; with the bound %lld "
      "valid, rms %.3f m (bound %.3f m)\n",
      dim, kDistance_m, before.valid, before.values, before.valid_rms_m(), before.all_max_m, after.valid,
      after.valid_rms_m(), bound_m(cfg));
  EXPECT_GT(before.valid_fraction(), 0.99);
  EXPECT_GT(before.valid_rms_m(), bound_m(cfg));
  EXPECT_GT(before.all_max_m, 2.0);
  EXPECT_GT(after.valid, 100);
  EXPECT_LT(after.valid_rms_m(), bound_m(cfg));
  EXPECT_LT(after.valid_fraction(), 0.5);
}

}  // namespace
}  // namespace rangesim::systemc::lockin
