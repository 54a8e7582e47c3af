// The tap codes' own laws (systemc/tof_lockin/code_law.h, config simulation.code_tables): the
// alias table of a code against the convolution of the Poisson count and the normal noise summed
// independently here (long double, erfcl, the count's pmf by Stirling's series), and the Monte
// Carlo trials drawn from the code laws against the trials that draw the count and the noise
// (the same stated test as the other skips, on 200,000 trials per path: means and variances
// within 5 standard errors, KS p >= 0.001, different seeds; its companion rejects 3 % more signal). Where a tap can reach
// V_sat the trials keep drawing count and noise, bit for bit.
#include <gtest/gtest.h>

#include <cmath>

#include "../systemc/tof_lockin/lockin_sc_test_util.h"
#include "app/bench/bench_stats.h"
#include "systemc/tof_lockin/code_law.h"
#include "systemc/tof_lockin/montecarlo.h"

namespace rangesim::systemc::lockin {
namespace {

using app::bench::compare_samples;

long double poisson_pmf(long double m, long long k) {
  if (k < 16) return std::exp(-m + k * std::log(m) - std::lgamma(static_cast<long double>(k) + 1));
  const long double kk = static_cast<long double>(k), d = m - kk, ik = 1 / kk, ik2 = ik * ik;
  const long double r = ik * (1.0L / 12 - ik2 * (1.0L / 360 - ik2 * (1.0L / 1260 - ik2 / 1680)));
  return std::exp(kk * std::log1p(d / kk) - d - 0.5L * std::log(2 * std::acos(-1.0L) * kk) - r);
}

TEST(TapCodeLaw, TableIsTheExactConvolution) {
  const TofLockinConfig cfg = test::edited_config({});
  const LockinPixelKernel::Readout r = LockinPixelKernel::Readout::of(cfg);
  const ColumnAdcKernel adc(cfg);
  const double offset_e = cfg.pixel.offset_voltage_V * cfg.pixel.source_follower_gain / r.volts_per_e[0];
  for (double frame_e : {1560.0, 15600.0, 45000.0}) {  // ambient frame, LED taps of a 0.5 nA wall
    std::vector<double> means{frame_e};
    means.push_back(frame_e);
    FrameLaws laws;
    const double offsets[2] = {offset_e, offset_e};
    laws.build(cfg, means, offsets, PoissonTables::Never, 1);
    const TapFrameLaw& law = laws.pixel(0)[0];
    ASSERT_FALSE(law.may_saturate);
    const AliasTable t = tap_code_table(law, r, adc, 0);
    const std::vector<long double> got = t.probabilities();
    // P(code = c) = sum_N p(N) [Phi(((c+1) LSB - mu_N) / sigma) - Phi((c LSB - mu_N) / sigma)], every N within 12
    // sigma.
    const long double m = law.count_mean_e, sd = std::sqrt(m), lsb = adc.lsb_V(), s = law.sigma_V;
    long double worst = 0, inside = 0;
    for (long long c = t.first(); c <= t.last(); ++c) {
      long double p = 0;
      for (long long n = std::max(0LL, static_cast<long long>(m - 12 * sd)); n <= static_cast<long long>(m + 12 * sd);
           ++n) {
        const long double mu = r.volts_per_e[0] * (n - law.offset_e) + r.a_sf * r.offset_V;
        const long double lo = c == 0 ? -1e300L : (c * lsb - mu) / s,
                          hi = c == adc.top_code() ? 1e300L : ((c + 1) * lsb - mu) / s;
        // Phi(hi) - Phi(lo) without cancellation: through the tail on the side away from the mean.
        const long double d = hi < 0 ? 0.5L * (std::erfc(-hi / std::sqrt(2.0L)) - std::erfc(-lo / std::sqrt(2.0L)))
                                     : 0.5L * (std::erfc(lo / std::sqrt(2.0L)) - std::erfc(hi / std::sqrt(2.0L)));
        p += poisson_pmf(m, n) * d;
      }
      inside += p;
      worst = std::max(worst, std::fabs(got[static_cast<std::size_t>(c - t.first())] - p));
    }
    EXPECT_LT(static_cast<double>(worst), 1e-15) << frame_e;
    EXPECT_LT(static_cast<double>(1 - inside), 1e-15) << frame_e;  // the table's codes hold all the mass
  }
}

std::vector<double> trial_errors(const TofLockinConfig& cfg, long long code_tables_from, double signal_A,
                                 std::uint64_t key, int trials) {
  const auto p = mc::TofLockinMc(cfg, true, code_tables_from).point(signal_A, 1e-10, key);
  std::vector<double> e;
  for (int t = 0; t < trials; ++t) {
    const mc::McTrial r = p->trial(t);
    if (r.detected) e.push_back(r.error);
  }
  return e;
}

TEST(TapCodeLaw, TrialsIndistinguishableFromCountAndNoise) {
  const TofLockinConfig cfg = test::edited_config({});
  const std::vector<double> codes = trial_errors(cfg, 0, 5e-10, 1, 200000),
                            draws = trial_errors(cfg, 1LL << 40, 5e-10, 2, 200000);
  ASSERT_EQ(codes.size(), 200000u);
  const auto c = compare_samples(codes, draws);
  EXPECT_TRUE(c.indistinguishable()) << c.mean_z << " SE (mean), " << c.var_z << " SE (variance), KS p " << c.ks_p;
  // At 9 m, 0.03 nA: the SNR-7 point where the ratio is least linear (range-noise bound off).
  TofLockinConfig weak = cfg;
  weak.eval.distance_m = 9.0;
  const auto w =
      compare_samples(trial_errors(weak, 0, 3e-11, 3, 200000), trial_errors(weak, 1LL << 40, 3e-11, 4, 200000));
  EXPECT_TRUE(w.indistinguishable()) << w.mean_z << " SE (mean), " << w.var_z << " SE (variance), KS p " << w.ks_p;
}

TEST(TapCodeLaw, TestRejectsThreePercentMoreSignal) {
  const TofLockinConfig cfg = test::edited_config({});
  const auto c =
      compare_samples(trial_errors(cfg, 0, 3e-11 * 1.03, 5, 200000), trial_errors(cfg, 1LL << 40, 3e-11, 6, 200000));
  EXPECT_FALSE(c.indistinguishable()) << c.mean_z << " SE (mean), " << c.var_z << " SE (variance), KS p " << c.ks_p;
}

// Near saturation the clip can act: no code tables, the trials are the per-draw trials bit for bit.
TEST(TapCodeLaw, SaturatingTapsKeepTheirDraws) {
  TofLockinConfig cfg = test::edited_config({});
  cfg.eval.distance_m = 0.3;
  const std::vector<double> a = trial_errors(cfg, 0, 2.85e-9, 7, 500),
                            b = trial_errors(cfg, 1LL << 40, 2.85e-9, 7, 500);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a[i], b[i]);
}

}  // namespace
}  // namespace rangesim::systemc::lockin
