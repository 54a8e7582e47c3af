// Monte Carlo of the same model, cycle by cycle, against the closed forms: the expected
// histogram (bin counts within 5 standard errors) and the estimator's mean and variance (within
// 5 standard errors), at a low-rate point and a pile-up-heavy one.
//
// The simulation is independent of the closed form's bin integrals and chain: photons of the TDC
// group arrive in continuous time (Poisson background from the arming time on, Poisson number of
// Gaussian echo photons), the first one stops the TDC, the bin comes from the actual edges, the
// hit is ours with probability 1 / s, and the blocking re-arms the group after the same number of
// phase bins as in the model.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

#include "golden/tof_spad/point_model.h"
#include "spad_test_helpers.h"

namespace rangesim::golden::spad {
namespace {

class CycleSimulator {
 public:
  CycleSimulator(const SpadModel& m, double signal_Hz, double background_Hz, double distance_m, unsigned long long seed)
      : m_(m),
        a_(make_arrivals(m.config(), signal_Hz, background_Hz, distance_m)),
        in_(m.pile_up_input({})),
        rng_(seed) {}

  // One histogram of n cycles (state carries over from the previous call, as a sensor's does).
  HistogramCounts run(long n) {
    const TdcBins& b = m_.bins();
    const int np = b.phase_bins, codes = b.codes;
    const double s = m_.share(), period = b.period_s;
    const double bg_rate = s * a_.live_fraction * a_.uniform_rate_Hz;
    std::poisson_distribution<int> echo_photons(s * a_.live_fraction * a_.signal_per_cycle);
    std::normal_distribution<double> jitter(a_.round_trip_s, a_.irf_sigma_s);
    std::exponential_distribution<double> background(bg_rate > 0 ? bg_rate : 1.0);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    HistogramCounts h{std::vector<double>(static_cast<size_t>(codes), 0.0), {}, s};
    std::vector<double> armed_diff(static_cast<size_t>(np) + 1, 0.0);
    for (long c = 0; c < n; ++c) {
      if (blind_ > 0) {
        --blind_;
        continue;
      }
      const double t_arm = b.edges_s[static_cast<size_t>(phase_)];
      double t = bg_rate > 0 ? t_arm + background(rng_) : INFINITY;
      for (int k = echo_photons(rng_); k > 0; --k) {
        const double x = jitter(rng_);
        if (x >= t_arm && x >= 0 && x < period) t = std::min(t, x);
      }
      armed_diff[static_cast<size_t>(phase_)] += 1;
      if (!(t < period)) {  // no hit: armed to the end, next cycle from START
        armed_diff[static_cast<size_t>(np)] -= 1;
        phase_ = 0;
        continue;
      }
      const int i = static_cast<int>(std::upper_bound(b.edges_s.begin(), b.edges_s.end(), t) - b.edges_s.begin()) - 1;
      armed_diff[static_cast<size_t>(i) + 1] -= 1;
      if (i < codes && unit(rng_) * s < 1.0) h.events[static_cast<size_t>(i)] += 1;
      const long dest = i + (i < codes ? in_.block_event_bins : in_.block_overflow_bins);
      if (dest < np) {
        phase_ = 0;
      } else {
        phase_ = static_cast<int>(dest % np);
        blind_ = dest / np - 1;
      }
    }
    double armed = 0;
    for (int i = 0; i < codes; ++i) h.armed.push_back(armed += armed_diff[static_cast<size_t>(i)]);
    return h;
  }

 private:
  const SpadModel& m_;
  Arrivals a_;
  PileUpInput in_;
  std::mt19937_64 rng_;
  int phase_ = 0;
  long blind_ = 0;
};

struct McPoint {
  const char* name;
  double signal_Hz, background_Hz, distance_m;
};
// Low rate: ~2% of the cycles stop the shared TDC. Pile-up heavy: the group sees ~1 background
// photon per cycle; 4-cycle blocking after every hit; only ~12% of the cycles are armed at the
// echo.
const McPoint kLowRate{"low-rate", 1e6, 1e4, 2.2};
const McPoint kPileUp{"pile-up", 4e6, 2e7, 2.2};

TofSpadConfig config_with_cycles(double cycles) {
  TofSpadConfig cfg = test::preset_config();
  cfg.histogram.integration_time_s = cycles / cfg.laser.repetition_rate_Hz;
  cfg.evaluation.frames_averaged = 1;
  return cfg;
}

void check_histogram(const McPoint& pt) {
  const long n = 200000;
  const SpadModel m(config_with_cycles(static_cast<double>(n)));
  CycleSimulator sim(m, pt.signal_Hz, pt.background_Hz, pt.distance_m, 12345);
  sim.run(20000);  // reach the stationary arming phase first
  const HistogramCounts h = sim.run(n);
  const PileUpHistogram p = m.histogram(pt.signal_Hz, pt.background_Hz, pt.distance_m);
  double worst = 0, total = 0, expected_total = 0;
  for (size_t i = 0; i < h.events.size(); ++i) {
    const double mean = n * p.event_prob[i];
    const double z = (h.events[i] - mean) / std::sqrt(std::max(mean, 1.0));
    worst = std::max(worst, std::fabs(z));
    EXPECT_LT(std::fabs(z), 5.0) << pt.name << " bin " << i << ": " << h.events[i] << " vs " << mean;
    const double armed_mean = n * p.armed_prob[i];
    EXPECT_NEAR(h.armed[i], armed_mean, 5 * std::sqrt(armed_mean) + 0.01 * armed_mean) << pt.name << " bin " << i;
    total += h.events[i], expected_total += mean;
  }
  EXPECT_NEAR(total, expected_total, 5 * std::sqrt(expected_total)) << pt.name;
  std::printf("MC histogram %s: %.0f events vs %.1f expected, worst bin |z| = %.2f\n", pt.name, total, expected_total,
              worst);
}

TEST(SpadMonteCarlo, ExpectedHistogramLowRate) { check_histogram(kLowRate); }
TEST(SpadMonteCarlo, ExpectedHistogramPileUp) { check_histogram(kPileUp); }

// Estimator moments: `trials` histograms of `cycles` cycles each.
void check_estimator(const McPoint& pt, bool coates, double cycles, int trials) {
  const SpadModel m(config_with_cycles(cycles));
  const EstimatorConfig est{7, coates, true};
  const PointResult cf = m.evaluate(pt.signal_Hz, pt.background_Hz, pt.distance_m, est);
  ASSERT_EQ(cf.detect, "detectable") << pt.name;
  CycleSimulator sim(m, pt.signal_Hz, pt.background_Hz, pt.distance_m, coates ? 777 : 778);
  sim.run(20000);
  double sum = 0, sum2 = 0;
  int missed = 0;
  const double t0 = 2 * pt.distance_m / 299792458.0;
  for (int k = 0; k < trials; ++k) {
    const auto t = estimate_time_s(sim.run(static_cast<long>(cycles)), m.bins(), est);
    if (!t) {
      ++missed;
      continue;
    }
    const double e = *t - t0;
    sum += e, sum2 += e * e;
  }
  const int n = trials - missed;
  const double mean = sum / n, var = (sum2 - n * mean * mean) / (n - 1);
  const double cf_mean = cf.moments.mean_s - t0, cf_var = cf.moments.var_s2;
  const double se_mean = std::sqrt(cf_var / n), se_var = cf_var * std::sqrt(2.0 / (n - 1));
  std::printf("MC estimator %s %s: mean %.3f ps (closed %.3f, SE %.3f), std %.3f ps (closed %.3f), %d missed\n",
              pt.name, coates ? "Coates" : "raw", mean * 1e12, cf_mean * 1e12, se_mean * 1e12, std::sqrt(var) * 1e12,
              std::sqrt(cf_var) * 1e12, missed);
  EXPECT_EQ(missed, 0);
  EXPECT_NEAR(mean, cf_mean, 5 * se_mean) << pt.name;
  EXPECT_NEAR(var, cf_var, 5 * se_var) << pt.name;
}

TEST(SpadMonteCarlo, EstimatorLowRateCoates) { check_estimator(kLowRate, true, 20000, 1000); }
TEST(SpadMonteCarlo, EstimatorLowRateRaw) { check_estimator(kLowRate, false, 20000, 1000); }
TEST(SpadMonteCarlo, EstimatorPileUpCoates) { check_estimator(kPileUp, true, 40000, 1000); }
TEST(SpadMonteCarlo, EstimatorPileUpRaw) { check_estimator(kPileUp, false, 40000, 1000); }

}  // namespace
}  // namespace rangesim::golden::spad
