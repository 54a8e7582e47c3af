// Monte Carlo of the same physics, cycle by cycle, against the closed forms: the expected
// histogram (bin counts within 5 standard errors) and the estimator's mean and variance (within
// 5 standard errors), at a low-rate point and a pile-up-heavy one.
//
// The simulation is independent of the closed form's bins, laws and chain: every SPAD of the TDC
// group is followed in continuous time (Poisson background, Poisson-many Gaussian echo photons
// per pulse at the laser pulse's width, non-paralysable dead time from the true arrival), each
// avalanche's recorded time jittered, the first recorded avalanche at or after the arming stops
// the TDC, its bin comes from the actual edges, and the TDC re-arms at the start of that bin +
// the blocking (or at the next START).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <queue>
#include <random>

#include "golden/tof_spad/point_model.h"
#include "spad_test_helpers.h"

namespace rangesim::golden::spad {
namespace {

class GroupSimulator {
 public:
  GroupSimulator(const SpadModel& m, double signal_Hz, double background_Hz, double distance_m, unsigned long long seed)
      : m_(m), a_(make_arrivals(m.config(), signal_Hz, background_Hz, distance_m)), rng_(seed) {
    const PileUpInput blocks = m.pile_up_input({});
    block_event_ = blocks.block_event_bins, block_overflow_ = blocks.block_overflow_bins;
    spads_.resize(static_cast<size_t>(m.config().tdc.columns_per_tdc));
  }

  // One histogram of n cycles of SPAD 0 (state carries over from the previous call, as a sensor's does).
  HistogramCounts run(long n) {
    const TdcBins& b = m_.bins();
    const int np = b.phase_bins, codes = b.codes;
    const double period = b.period_s, dead = m_.config().spad.dead_time_s;
    HistogramCounts h{std::vector<double>(static_cast<size_t>(codes), 0.0), {}, m_.share()};
    std::vector<double> armed_diff(static_cast<size_t>(np) + 1, 0.0);
    double full_cycles = 0;
    // Armed bins [from, to] (bins counted from this run's first START).
    const auto add_armed = [&](long long from, long long to) {
      from = std::max(from, 0LL);  // armed since before this run
      if (from > to) return;
      const long long kf = from / np, kt = to / np;
      const int pf = static_cast<int>(from % np), pt = static_cast<int>(to % np);
      if (kf == kt) {
        armed_diff[static_cast<size_t>(pf)] += 1, armed_diff[static_cast<size_t>(pt) + 1] -= 1;
        return;
      }
      armed_diff[static_cast<size_t>(pf)] += 1, armed_diff[static_cast<size_t>(np)] -= 1;
      full_cycles += static_cast<double>(kt - kf - 1);
      armed_diff[0] += 1, armed_diff[static_cast<size_t>(pt) + 1] -= 1;
    };
    armed_from_ -= static_cast<long long>(np) * done_;  // bins relative to this run
    t0_ += static_cast<double>(done_) * period;
    done_ = n;
    for (;;) {
      // The next avalanche of the group (SPADs are independent: the earliest one's).
      int who = 0;
      for (size_t j = 1; j < spads_.size(); ++j)
        if (next(j) < next(static_cast<size_t>(who))) who = static_cast<int>(j);
      const double t = next(static_cast<size_t>(who)) - t0_;
      if (t >= static_cast<double>(n) * period) break;
      fire(static_cast<size_t>(who), dead);
      const long long cycle = static_cast<long long>(std::floor(t / period));
      const double phase = t - static_cast<double>(cycle) * period;
      const int bin = std::clamp(
          static_cast<int>(std::upper_bound(b.edges_s.begin(), b.edges_s.end(), phase) - b.edges_s.begin()) - 1, 0,
          np - 1);
      const long long abs_bin = cycle * np + bin;
      if (abs_bin < armed_from_) continue;  // the TDC is blind
      add_armed(armed_from_, abs_bin);
      if (bin < codes && who == 0) h.events[static_cast<size_t>(bin)] += 1;
      armed_from_ = std::max(abs_bin + (bin < codes ? block_event_ : block_overflow_), (cycle + 1) * np);
    }
    add_armed(armed_from_, static_cast<long long>(n) * np - 1);
    double run = 0;
    for (int i = 0; i < codes; ++i) h.armed.push_back((run += armed_diff[static_cast<size_t>(i)]) + full_cycles);
    return h;
  }

 private:
  struct Spad {
    double dead_until = -1e300;
    double next_uniform = -1;   // absolute time of the next background / dark arrival
    long long echo_cycle = -1;  // cycle of the buffered echo photons
    std::vector<double> echo;   // their absolute times, latest first
    double next = -1;           // the next avalanche (absolute time), -1: to draw
    double recorded = -1;       // its recorded time (jittered)
  };

  // The SPAD's next arrival time (absolute).
  double arrival(Spad& s) {
    const double period = m_.bins().period_s;
    if (s.next_uniform < 0) s.next_uniform = draw_exp(a_.uniform_rate_Hz);
    while (s.echo.empty() && a_.signal_per_cycle > 0) {
      // Cycles without an echo photon are skipped (geometric), then a zero-truncated Poisson count.
      s.echo_cycle += 1 + static_cast<long long>(std::floor(draw_exp(1.0) / a_.signal_per_cycle));
      int k = 0;
      while (k == 0) k = std::poisson_distribution<int>(a_.signal_per_cycle)(rng_);
      std::normal_distribution<double> shape(a_.round_trip_s, a_.pulse_sigma_s);
      for (int i = 0; i < k; ++i) s.echo.push_back(static_cast<double>(s.echo_cycle) * period + shape(rng_));
      std::sort(s.echo.begin(), s.echo.end(), std::greater<double>());
    }
    return std::min(s.next_uniform, s.echo.empty() ? INFINITY : s.echo.back());
  }
  void consume(Spad& s, double t) {
    if (!s.echo.empty() && s.echo.back() == t)
      s.echo.pop_back();
    else
      s.next_uniform += draw_exp(a_.uniform_rate_Hz);
  }
  // The SPAD's next avalanche: its first arrival while live (dead time from there); returns its
  // recorded (jittered) time.
  double next(size_t j) {
    Spad& s = spads_[j];
    while (s.next < 0) {
      const double t = arrival(s);
      consume(s, t);
      if (t >= s.dead_until) s.next = t, s.recorded = t + a_.jitter_sigma_s * std::normal_distribution<double>()(rng_);
    }
    return s.recorded;
  }
  void fire(size_t j, double dead) { spads_[j].dead_until = spads_[j].next + dead, spads_[j].next = -1; }
  double draw_exp(double rate) { return rate > 0 ? std::exponential_distribution<double>(rate)(rng_) : INFINITY; }

  const SpadModel& m_;
  Arrivals a_;
  std::mt19937_64 rng_;
  long long block_event_ = 0, block_overflow_ = 0;
  std::vector<Spad> spads_;
  long long armed_from_ = 0, done_ = 0;
  double t0_ = 0;
};

struct McPoint {
  const char* name;
  double signal_Hz, background_Hz, distance_m;
};
// Low rate: ~2% of the cycles stop the shared TDC. Pile-up heavy: the group sees ~1 background
// photon per cycle (each SPAD 0.6 per dead time); 4-cycle blocking after every hit; only ~12% of
// the cycles are armed at the echo.
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
  GroupSimulator sim(m, pt.signal_Hz, pt.background_Hz, pt.distance_m, 12345);
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

// Estimator moments: `trials` histograms of `cycles` cycles each. `systematic_s`: the mean's
// allowed systematic gap. The renewal chain's one approximation (the losers' laws independent)
// shifts the echo's centroid when several SPADs of the group fire on the same echo: 1.7 ps at the
// pile-up point (0.1 photons per SPAD and pulse, 4 columns), nothing measurable with one column
// or at the evaluation grid's 1 Mcounts/s (SpadGolden.EstimatorMomentsCoatesGridMaxSignal).
void check_estimator(const McPoint& pt, bool coates, double cycles, int trials, double systematic_s = 0) {
  const SpadModel m(config_with_cycles(cycles));
  const EstimatorConfig est{7, coates, true};
  const PointResult cf = m.evaluate(pt.signal_Hz, pt.background_Hz, pt.distance_m, est);
  ASSERT_EQ(cf.detect, "detectable") << pt.name;
  GroupSimulator sim(m, pt.signal_Hz, pt.background_Hz, pt.distance_m, coates ? 777 : 778);
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
  EXPECT_NEAR(mean, cf_mean, 5 * se_mean + systematic_s) << pt.name;
  EXPECT_NEAR(var, cf_var, 5 * se_var) << pt.name;
}

TEST(SpadMonteCarlo, EstimatorLowRateCoates) { check_estimator(kLowRate, true, 20000, 1000); }
TEST(SpadMonteCarlo, EstimatorLowRateRaw) { check_estimator(kLowRate, false, 20000, 1000); }
TEST(SpadMonteCarlo, EstimatorPileUpCoates) { check_estimator(kPileUp, true, 40000, 1000, 2e-12); }
TEST(SpadMonteCarlo, EstimatorPileUpRaw) { check_estimator(kPileUp, false, 40000, 1000, 2e-12); }

}  // namespace
}  // namespace rangesim::golden::spad
