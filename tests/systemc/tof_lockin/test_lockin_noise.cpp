// With noise, the mean and variance of L over many simulated range maps agree
// with the golden closed form (golden::evaluate_point -> range_moments) within
// 5 standard errors, both with the aggregated shot noise (Poisson of the
// frame's total mean) and with one Poisson draw per gate window and
// accumulation.
#include <gtest/gtest.h>

#include <cmath>
#include <fmt/format.h>

#include "golden/tof_lockin/lockin_point.h"
#include "lockin_sc_test_util.h"

namespace rangesim::systemc::lockin {
namespace {

using test::Edit;

void check_moments(const TofLockinConfig& cfg, bool aggregate, double is, double ib, double L, int columns, int maps,
                   std::uint64_t seed) {
  SCOPED_TRACE(fmt::format("I_s {:g} I_b {:g} L {:g} aggregate {}", is, ib, L, aggregate));
  const golden::LockinPoint pt = golden::evaluate_point(cfg, is, ib, L, 1);
  ASSERT_EQ(pt.detect, golden::LockinDetect::Detectable);
  const int per_map = cfg.readout.ambient_subtraction ? 2 : 1;
  TofLockinSensorKernel k(cfg, LockinSimOptions{true, true, aggregate, seed}, 1, columns,
                          test::uniform(columns, is, ib, L), static_cast<long long>(maps) * per_map);
  k.run();
  double s1 = 0, s2 = 0;
  long long n = 0;
  std::vector<double> v;
  for (long long m = 0; m < k.range_maps(); ++m)
    for (int c = 0; c < columns; ++c) {
      const double x = k.range_m(m, 0, c);
      ASSERT_TRUE(std::isfinite(x));
      v.push_back(x), s1 += x, ++n;
    }
  const double mean = s1 / n;
  double m4 = 0;
  for (double x : v) s2 += (x - mean) * (x - mean), m4 += std::pow(x - mean, 4);
  const double var = s2 / (n - 1);
  m4 /= n;
  const double se_mean = std::sqrt(var / n), se_var = std::sqrt((m4 - var * var) / n);
  EXPECT_NEAR(mean, pt.mean_m, 5 * se_mean) << "std " << std::sqrt(var) << " golden " << pt.std_m;
  EXPECT_NEAR(var, pt.std_m * pt.std_m, 5 * se_var) << "mean " << mean << " golden " << pt.mean_m;
}

TEST(LockinNoise, MomentsMatchGoldenAggregated) {
  const TofLockinConfig cfg = test::edited_config({{"pixel", "rows", "1"}});
  check_moments(cfg, true, 3e-10, 1e-10, 2.0, 50, 400, 11);
  check_moments(cfg, true, 1.2e-9, 1e-11, 9.0, 50, 400, 12);
}

TEST(LockinNoise, MomentsMatchGoldenPerAccumulation) {
  const TofLockinConfig cfg = test::edited_config({{"pixel", "rows", "1"}});
  check_moments(cfg, false, 3e-10, 1e-10, 5.0, 40, 150, 13);
}

TEST(LockinNoise, MomentsMatchGoldenNonIdealPixelNoAmbient) {
  const TofLockinConfig cfg = test::edited_config({{"pixel", "rows", "1"},
                                                   {"pixel", "charge_separation", "0.9"},
                                                   {"pixel", "drain_efficiency", "0.98"},
                                                   {"source", "rise_time_s", "8e-9"},
                                                   {"readout", "ambient_subtraction", "false"},
                                                   {"readout", "offset_calibration_V", "0.015"}});
  check_moments(cfg, true, 3e-10, 1e-10, 2.0, 50, 600, 14);
}

TEST(LockinNoise, CdsRemovesKtc) {
  // With CDS, no read noise and no shot noise of the offset charge, the ambient
  // frame of a dark pixel reads the FD offset + dark only.
  const TofLockinConfig cfg = test::edited_config({{"pixel", "rows", "1"},
                                                   {"readout", "cds_enabled", "true"},
                                                   {"noise", "read_noise_V", "0"},
                                                   {"offset_charge", "shot_noise", "false"},
                                                   {"noise", "dark_current_A", "0"}});
  TofLockinSensorKernel k(cfg, LockinSimOptions{true, true, true, 5}, 1, 8, test::uniform(8, 0, 0, 1.0), 2);
  k.run();
  for (int c = 0; c < 8; ++c) EXPECT_DOUBLE_EQ(k.adc_input_V(1, 0, c, 0), cfg.pixel.offset_voltage_V);
}

}  // namespace
}  // namespace rangesim::systemc::lockin

namespace rangesim::systemc::lockin {
namespace {

// Every ADC code and input of a run, with its frame records' cycles.
std::vector<double> run_outputs(const TofLockinSensorKernel& k, int columns) {
  std::vector<double> v;
  for (const auto& r : k.frame_records())
    for (long long c : r.cycles) v.push_back(static_cast<double>(c));
  for (long long f = 0; f < static_cast<long long>(k.frame_records().size()); ++f)
    for (int c = 0; c < columns; ++c)
      for (int t = 0; t < 2; ++t) {
        v.push_back(static_cast<double>(k.code(f, 0, c, t)));
        v.push_back(k.adc_input_V(f, 0, c, t));
      }
  return v;
}

// Monte Carlo reuses one kernel for all the trials of a point (restart): a restarted kernel gives
// the same bits as a new kernel with the same seed, aggregated and per accumulation, whatever ran
// on it before.
TEST(LockinRestart, RestartedKernelEqualsNewKernel) {
  const TofLockinConfig cfg = test::edited_config({{"pixel", "rows", "1"}});
  for (const bool aggregate : {true, false}) {
    SCOPED_TRACE(aggregate ? "aggregated" : "per accumulation");
    const int columns = 3;
    const auto stim = test::uniform(columns, 3e-10, 1e-10, 2.0);
    TofLockinSensorKernel reused(cfg, LockinSimOptions{true, true, aggregate, 7}, 1, columns, stim, 4);
    reused.run();
    const std::vector<double> first = run_outputs(reused, columns);
    for (const std::uint64_t seed : {8ULL, 7ULL, 123456789ULL}) {
      reused.restart(seed);
      reused.run();
      TofLockinSensorKernel fresh(cfg, LockinSimOptions{true, true, aggregate, seed}, 1, columns, stim, 4);
      fresh.run();
      EXPECT_EQ(run_outputs(reused, columns), run_outputs(fresh, columns)) << "seed " << seed;
      EXPECT_EQ(reused.events(), fresh.events());
      EXPECT_EQ(reused.time_s(), fresh.time_s());
      ASSERT_TRUE(std::isfinite(fresh.range_m(1, 0, 2)));
      EXPECT_EQ(reused.range_m(1, 0, 2), fresh.range_m(1, 0, 2));
      if (seed == 7) {
        EXPECT_EQ(run_outputs(reused, columns), first);
      }
      if (seed == 8) {
        EXPECT_NE(run_outputs(reused, columns), first) << "the seed must reach the draws";
      }
    }
  }
}

}  // namespace
}  // namespace rangesim::systemc::lockin
