// TDC bins (INL bow + seeded DNL) and the per-bin arrival means of the tof-spad golden model.
#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

#include "golden/tof_spad/arrival_rates.h"
#include "golden/tof_spad/tdc_bins.h"
#include "spad_test_helpers.h"

namespace rangesim::golden::spad {
namespace {

TEST(SpadTdcBins, PresetGeometry) {
  const TofSpadConfig cfg = test::preset_config();
  const TdcBins b = make_tdc_bins(cfg.tdc, 1.0 / cfg.laser.repetition_rate_Hz);
  EXPECT_EQ(b.phase_bins, 256);  // 25 ns / 97.65625 ps
  EXPECT_EQ(b.codes, 256);       // the 100 ns TDC range is longer than the period
  ASSERT_EQ(b.edges_s.size(), 257u);
  EXPECT_EQ(b.edges_s.front(), 0.0);
  EXPECT_DOUBLE_EQ(b.edges_s.back(), 25e-9);
  for (int i = 0; i < b.phase_bins; ++i) EXPECT_GT(b.width_s(i), 0.0) << i;
}

TEST(SpadTdcBins, NonlinearityStatisticsFollowTheConfig) {
  TdcConfig tdc = test::preset_config().tdc;
  tdc.inl_rms_lsb = 0.0;
  tdc.dnl_rms_lsb = 0.1;
  const TdcBins b = make_tdc_bins(tdc, 25e-9);
  double dnl2 = 0;
  for (int i = 0; i + 1 < b.codes; ++i) dnl2 += std::pow(b.width_s(i) / b.lsb_s - 1, 2);
  EXPECT_NEAR(std::sqrt(dnl2 / (b.codes - 1)), 0.1, 0.015);  // 255 draws: ~5% sampling error
  tdc.dnl_rms_lsb = 0.0;
  tdc.inl_rms_lsb = 0.4;
  const TdcBins bow = make_tdc_bins(tdc, 25e-9);
  double inl2 = 0;
  for (int i = 0; i < bow.codes; ++i) inl2 += std::pow(bow.edges_s[static_cast<size_t>(i)] / bow.lsb_s - i, 2);
  EXPECT_NEAR(std::sqrt(inl2 / bow.codes), 0.4, 1e-9);  // exact rms of a whole sine period
}

TEST(SpadTdcBins, SeededPatternIsDeterministic) {
  TdcConfig tdc = test::preset_config().tdc;
  const TdcBins a = make_tdc_bins(tdc, 25e-9), b = make_tdc_bins(tdc, 25e-9);
  EXPECT_EQ(a.edges_s, b.edges_s);
  tdc.nonlinearity_seed += 1;
  EXPECT_NE(make_tdc_bins(tdc, 25e-9).edges_s, a.edges_s);
  EXPECT_NEAR(keyed_normal(7, 3), keyed_normal(7, 3), 0.0);
}

TEST(SpadTdcBins, ShortTdcRangeOverflows) {
  TdcConfig tdc = test::preset_config().tdc;
  tdc.full_range_s = 10e-9;  // shorter than the 25 ns period: later hits give no code
  const TdcBins b = make_tdc_bins(tdc, 25e-9);
  EXPECT_EQ(b.codes, 102);
  EXPECT_EQ(b.phase_bins, 256);
}

TEST(SpadArrivals, IrfAndLiveFraction) {
  const TofSpadConfig cfg = test::preset_config();
  // sqrt((0.4247 x 100 ps)^2 + (60 ps)^2) = 73.5 ps
  EXPECT_NEAR(irf_sigma_s(cfg), 73.5076e-12, 1e-15);
  const Arrivals a = make_arrivals(cfg, 1e6, 1e7, 3.0);
  EXPECT_NEAR(a.round_trip_s, 2 * 3.0 / 299792458.0, 1e-18);
  EXPECT_NEAR(a.signal_per_cycle, 0.025, 1e-15);
  EXPECT_NEAR(a.live_fraction, 1 / (1 + (1e6 + 1e7 + 100) * 50e-9), 1e-15);  // non-paralysable
}

TEST(SpadArrivals, BinsConserveTheMeanPhotonsPerCycle) {
  const TofSpadConfig cfg = test::preset_config();
  const TdcBins b = make_tdc_bins(cfg.tdc, 25e-9);
  const Arrivals a = make_arrivals(cfg, 4e5, 2e6, 2.0);
  const std::vector<double> r = photons_per_bin(b, a);
  const double total = std::accumulate(r.begin(), r.end(), 0.0);
  EXPECT_NEAR(total, a.live_fraction * (a.signal_per_cycle + a.uniform_rate_Hz * 25e-9), 1e-12);
  // The echo sits in the bin that holds 2 L / c.
  const auto peak = std::max_element(r.begin(), r.end()) - r.begin();
  EXPECT_GE(a.round_trip_s, b.edges_s[static_cast<size_t>(peak)] - b.lsb_s);
  EXPECT_LE(a.round_trip_s, b.edges_s[static_cast<size_t>(peak) + 1] + b.lsb_s);
}

}  // namespace
}  // namespace rangesim::golden::spad
