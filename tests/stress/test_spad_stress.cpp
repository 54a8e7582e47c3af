// Stress and property tests of tof-spad (label: stress): the golden point model (arrivals ->
// pile-up chain -> estimator) and the clock-level kernels (SPAD pixel, TDC group) over extreme
// but legal inputs: count rates 0 .. 1e10 Hz (far above 1 / dead time), dead and busy time from
// 0 to the laser period, TDC LSB 1 ps .. 1 ns, 1 .. 24 bits. Invariants:
//   - no NaN/Inf in any PointResult field or expected histogram; probabilities in [0, 1]; the
//     expected events per cycle at most 1;
//   - more signal never loses detection below pile-up saturation;
//   - the kernel's TDC code of a phase equals the golden bin search (exact);
//   - kernel histograms are consistent (events <= armed cycles <= STARTs) at any rate;
//   - 95% confidence intervals of the kernel's events per histogram cover golden's exact mean;
//   - hazards: zero-truncated Poisson inversion underflow at > 745 photons per cycle (kernel);
//     photon phases exact after 100 s of integration (relative times, kernel);
//     Coates hazard rounding to 1 read as an empty bin (golden estimator).
#include <gtest/gtest.h>
#include <rapidcheck/gtest.h>

#include <algorithm>
#include <cmath>
#include <iomanip>

#include "core/physics.h"
#include "golden/tof_spad/point_model.h"
#include "stress_gen.h"
#include "stress_print.h"
#include "systemc/tof_spad/pixel_kernel.h"
#include "systemc/tof_spad/sensor_kernel.h"

namespace rangesim::golden::spad {
namespace {

using stress::log_uniform;
using stress::log_uniform_or_zero;

bool finite(double v) { return std::isfinite(v); }

// Legal configuration; the period holds 8 .. 2048 LSB (pile-up chain cost ~ bins x iterations).
rc::Gen<TofSpadConfig> spad_config_gen() {
  return rc::gen::exec([] {
    TofSpadConfig c;
    c.tdc.lsb_s = *log_uniform(1e-12, 1e-9);
    const double np = *log_uniform(8.0, 2048.0);
    c.laser.repetition_rate_Hz = 1.0 / (np * c.tdc.lsb_s);
    const double period = 1.0 / c.laser.repetition_rate_Hz;
    const int codes = std::max(1, static_cast<int>(std::floor(np * *rc::gen::element(1.0, 0.5, 0.1))));
    c.tdc.bits = std::max(static_cast<int>(std::ceil(std::log2(codes))), *rc::gen::inRange(1, 25));
    c.tdc.full_range_s = codes * c.tdc.lsb_s;
    c.tdc.dnl_rms_lsb = *rc::gen::element(0.0, 0.1, 1.0);
    c.tdc.inl_rms_lsb = *rc::gen::element(0.0, 0.3, 10.0);
    c.tdc.columns_per_tdc = *rc::gen::element(1, 4, 4096);
    c.tdc.neighbour_rate_fraction = *rc::gen::element(0.0, 0.5, 1.0);
    c.tdc.busy_time_s = *rc::gen::element(0.0, 1e-3, 0.5, 1.0) * period;
    c.spad.dead_time_s =
        *rc::gen::oneOf(rc::gen::element(0.0, period, 0.999 * period),
                        rc::gen::map(log_uniform(1e-6, 1.0), [period](double f) { return f * period; }));
    c.spad.dark_count_rate_Hz = *log_uniform_or_zero(1e-3, 1e9);
    c.spad.jitter_sigma_s = *log_uniform_or_zero(1e-13, 1e-6);
    c.laser.pulse_fwhm_s = *log_uniform(1e-13, 1e-6);
    c.histogram.integration_time_s = *log_uniform(1e-9, 1.0);
    c.histogram.peak_window_bins = *rc::gen::element(1, 2, 7, 1000000);
    c.histogram.coates_correction = *rc::gen::arbitrary<bool>();
    c.histogram.subtract_background = *rc::gen::arbitrary<bool>();
    c.evaluation.frames_averaged = *rc::gen::element(1, 100000);
    c.evaluation.detection_sigma = *log_uniform(1e-3, 100.0);
    c.evaluation.min_signal_counts = *log_uniform(1e-3, 1e9);
    c.evaluation.min_armed_fraction = *log_uniform(1e-9, 1.0);
    return c;
  });
}

rc::Gen<double> rate_gen() { return log_uniform_or_zero(1e-3, 1e10); }

// Distance whose echo lies inside the codes (or anywhere in the period, one time in 4).
double distance_in_codes(const TofSpadConfig& c, double u) {
  return 0.5 * phys::kSpeedOfLight_m_per_s * u * c.tdc.full_range_s;
}

void check_result(const PointResult& p) {
  const double f[] = {p.bias_m,
                      p.std_m,
                      p.accuracy_m,
                      p.signal_counts,
                      p.background_counts,
                      p.detections_per_cycle,
                      p.armed_at_echo,
                      p.background_per_bin,
                      p.cycles,
                      p.moments.mean_s,
                      p.moments.var_s2};
  for (double v : f) RC_ASSERT(finite(v));
  RC_ASSERT(p.std_m >= 0 && p.accuracy_m >= 0 && p.signal_counts >= 0 && p.background_counts >= 0);
  RC_ASSERT(p.detections_per_cycle >= 0 && p.detections_per_cycle <= 1 + 1e-9);
  RC_ASSERT(p.armed_at_echo >= 0 && p.armed_at_echo <= 1 + 1e-9);
}

RC_GTEST_PROP(SpadStress, AnyLegalPointIsFinite, ()) {
  const TofSpadConfig cfg = *spad_config_gen();
  const SpadModel model(cfg);
  const double d = distance_in_codes(cfg, *rc::gen::map(rc::gen::inRange(0, 1101), [](int i) { return i / 1000.0; }));
  const double bg = *rate_gen(), sig = *rate_gen();
  RC_LOG() << std::setprecision(17) << "signal_Hz=" << sig << " background_Hz=" << bg << " distance_m=" << d << "\n";
  const PointResult p = model.evaluate(sig, bg, d);
  RC_TAG(p.detect);
  check_result(p);
}

RC_GTEST_PROP(SpadStress, ExpectedHistogramIsAProbabilityLaw, ()) {
  const TofSpadConfig cfg = *spad_config_gen();
  const SpadModel model(cfg);
  const double d = distance_in_codes(cfg, *rc::gen::map(rc::gen::inRange(0, 1001), [](int i) { return i / 1000.0; }));
  const PileUpHistogram h = model.histogram(*rate_gen(), *rate_gen(), d);
  double sum = 0;
  for (double p : h.event_prob) RC_ASSERT(finite(p) && p >= 0 && p <= 1), sum += p;
  for (double a : h.armed_prob) RC_ASSERT(finite(a) && a >= 0 && a <= 1 + 1e-12);
  for (double q : h.hazard) RC_ASSERT(q >= 0 && q <= 1);
  RC_ASSERT(sum <= 1 + 1e-9);
  RC_LOG() << std::setprecision(17) << "cycles_per_live_cycle=" << h.cycles_per_live_cycle << " model=" << h.model
           << "\n";
  // 1e-9: the renewal chain sums its cycle lengths and armings over many bins and passes
  // (0.99999999999899969 seen at a 10.7 GHz laser rate).
  RC_ASSERT(finite(h.cycles_per_live_cycle) && h.cycles_per_live_cycle >= 1 - 1e-9);
  // Our pixel's share of the group's events is 1 / share exactly when every column sees the same
  // rates (or the neighbours none); otherwise the dead time makes it depend on the rates.
  const double f = cfg.tdc.neighbour_rate_fraction;
  if (cfg.tdc.columns_per_tdc == 1 || f == 0.0 || f == 1.0)
    RC_ASSERT(std::fabs(h.our_events_per_cycle * h.share - h.group_events_per_cycle) <=
              1e-12 + 1e-9 * h.group_events_per_cycle);
  else
    RC_ASSERT(h.our_events_per_cycle <= h.group_events_per_cycle * (1 + 1e-9) + 1e-12);
}

// A detectable echo stays detectable as the signal grows, until the TDC is stopped before the
// echo in nearly every cycle (pile_up_saturated).
RC_GTEST_PROP(SpadStress, MoreSignalNeverLosesDetection, ()) {
  const TofSpadConfig cfg = *spad_config_gen();
  const SpadModel model(cfg);
  const double d = distance_in_codes(cfg, *rc::gen::map(rc::gen::inRange(100, 901), [](int i) { return i / 1000.0; }));
  const double s1 = *log_uniform(1e-3, 1e10), s2 = std::min(1e10, s1 * *log_uniform(1.0, 1e6));
  const double b = *rate_gen();
  const PointResult p1 = model.evaluate(s1, b, d), p2 = model.evaluate(s2, b, d);
  RC_TAG(p1.detect + " -> " + p2.detect);
  if (p1.detect == "detectable" && p2.detect != "pile_up_saturated") RC_ASSERT(p2.detect == "detectable");
}

// Hazard: at s r > 37 per bin the hazard 1 - e^{-s r} rounds to 1. The Coates moments skipped
// such bins (q < 1 guard): the echo vanished from the centroid and a strong echo on a dark
// background came out "too_few_signal_counts". Echo over two bins, 1e4 photons per cycle.
TEST(SpadHazards, SaturatedEchoBinsKeepTheEcho) {
  TofSpadConfig cfg;
  cfg.laser.repetition_rate_Hz = 1e6;
  cfg.tdc.lsb_s = 1e-9;
  cfg.tdc.bits = 10;
  cfg.tdc.full_range_s = 1000e-9;
  cfg.tdc.dnl_rms_lsb = cfg.tdc.inl_rms_lsb = 0;
  cfg.tdc.columns_per_tdc = 1;
  cfg.tdc.busy_time_s = 0;
  cfg.spad.dead_time_s = 0;
  cfg.spad.jitter_sigma_s = 0;
  cfg.laser.pulse_fwhm_s = 1e-9;
  cfg.histogram.coates_correction = true;
  const SpadModel model(cfg);
  const double d = 0.5 * phys::kSpeedOfLight_m_per_s * 300e-9;  // echo on the edge of bins 299 / 300
  const PointResult weak = model.evaluate(1e9, 10, d), strong = model.evaluate(1e10, 10, d);
  EXPECT_EQ(weak.detect, "detectable");
  EXPECT_EQ(strong.detect, "detectable");
  EXPECT_TRUE(strong.moments.defined);
  // First-photon pile-up: at 1e4 photons per cycle the first one comes from the pulse's leading
  // edge, ~3 sigma = 1.3 ns early; the estimate must stay on that edge, not leave the echo.
  EXPECT_LT(strong.bias_m, 0.0);
  EXPECT_GT(strong.bias_m, -0.5 * phys::kSpeedOfLight_m_per_s * 3e-9) << "within three bins of the echo";
}

}  // namespace
}  // namespace rangesim::golden::spad

namespace rangesim::systemc::spad {
namespace {

using stress::log_uniform;

RC_GTEST_PROP(SpadKernelStress, TdcCodeEqualsGoldenBinSearch, ()) {
  const TofSpadConfig cfg = *golden::spad::spad_config_gen();
  const TofSpadKernel k(cfg, 1, cfg.tdc.columns_per_tdc, {});
  const auto& e = k.bins().edges_s;
  for (int i = 0; i < 50; ++i) {
    const double phase = *rc::gen::oneOf(
        rc::gen::map(rc::gen::inRange(0, 1 << 20), [&](int j) { return e.back() * j / double(1 << 20); }),
        rc::gen::map(rc::gen::inRange(0, k.phase_bins()), [&](int j) { return e[static_cast<size_t>(j)]; }));
    const int golden_bin = static_cast<int>(std::upper_bound(e.begin(), e.end(), phase) - e.begin()) - 1;
    RC_ASSERT(k.phase_bin(phase) == std::min(golden_bin, k.phase_bins() - 1));
  }
}

// One TDC group at any rate: its histogram is consistent and its estimate finite.
RC_GTEST_PROP(SpadKernelStress, GroupHistogramConsistent, ()) {
  TofSpadConfig cfg = *golden::spad::spad_config_gen();
  cfg.tdc.columns_per_tdc = *rc::gen::element(1, 2, 4);
  const double period = 1.0 / cfg.laser.repetition_rate_Hz;
  const long long cycles = *rc::gen::inRange(1, 200);
  cfg.histogram.integration_time_s = cycles * period;
  double s = *golden::spad::rate_gen(), b = *golden::spad::rate_gen();
  // Cost cap: at most ~2e5 arrivals per pixel.
  const double arrivals = (s + b + cfg.spad.dark_count_rate_Hz) * cfg.histogram.integration_time_s;
  if (arrivals > 2e5) s *= 2e5 / arrivals, b *= 2e5 / arrivals;
  const double rt = *rc::gen::map(rc::gen::inRange(0, 1001), [](int i) { return i / 1000.0; }) * period;
  const TofSpadKernel k(cfg, 1, cfg.tdc.columns_per_tdc, {*rc::gen::arbitrary<std::uint32_t>(), SpadNoise{}});
  const GroupHistogram g = k.simulate_group(0, 0, 0, [&](int, int) { return PixelRates{s, b, rt}; });
  RC_ASSERT(g.starts == k.laser_cycles());
  long long events = 0;
  for (int i = 0; i < k.codes(); ++i) {
    long long in_code = 0;
    for (const auto& px : g.events) in_code += px[static_cast<size_t>(i)];
    events += in_code;
    RC_ASSERT(in_code <= g.armed[static_cast<size_t>(i)]);
    RC_ASSERT(g.armed[static_cast<size_t>(i)] >= 0 && g.armed[static_cast<size_t>(i)] <= g.starts);
  }
  RC_ASSERT(events + g.overflows <= g.avalanches);
  RC_ASSERT(events + g.overflows <= g.starts);  // one hit per START at most
  RC_ASSERT(g.avalanches <= g.photons);
  const PixelResult p = k.make_pixel(0, 0, g, 0);
  if (p.time_s) RC_ASSERT(std::isfinite(*p.time_s));
}

// Hazard: the zero-truncated Poisson count per laser cycle was drawn by inversion from
// e^{-mu}, which underflows to 0 past mu ~ 745: every signal cycle then produced its cap of
// 100000 photons. 1000 photons per cycle over 50 cycles must give 50000 +- 5 sigma.
TEST(SpadHazards, ManyPhotonsPerCycleArePoisson) {
  TofSpadConfig cfg;
  cfg.spad.dead_time_s = 0;
  const double mu = 1000, cycles = 50;
  SpadPixelKernel px(cfg, {mu * cfg.laser.repetition_rate_Hz, 0, 10e-9}, SpadNoise::none(),
                     static_cast<long long>(cycles), 5, 0, 0, 0);
  long long n = 0;
  while (!px.done() && n < 100000000) px.pop(), ++n;
  EXPECT_NEAR(static_cast<double>(px.photons()), mu * cycles, 5 * std::sqrt(mu * cycles));
}

// 95% confidence intervals (n = 40 histograms) of the events per histogram cover golden's mean
// cycles x P(event per cycle) in 182..200 of 200 repetitions. No dead time, no busy time, one
// pixel per TDC: golden's first-photon law is exact there.
TEST(SpadKernelStress, ConfidenceIntervalsCoverTheMean) {
  TofSpadConfig cfg;
  cfg.spad.dead_time_s = 0;
  cfg.spad.afterpulse_probability = 0;
  cfg.tdc.busy_time_s = 0;
  cfg.tdc.columns_per_tdc = 1;
  cfg.histogram.integration_time_s = 200 / cfg.laser.repetition_rate_Hz;
  const double s = 4e6, b = 2e6, d = 3.0;
  const golden::spad::SpadModel model(cfg);
  const golden::spad::PileUpHistogram h = model.histogram(s, b, d);
  const TofSpadKernel k(cfg, 1, 1, {});
  double p_event = 0;
  for (double p : h.event_prob) p_event += p;
  const double truth = p_event * static_cast<double>(k.laser_cycles());
  const double rt = 2 * d / phys::kSpeedOfLight_m_per_s;
  const int reps = 200, n = 40;
  const double t975 = 2.0227;  // Student t, 39 degrees of freedom
  int covered = 0;
  for (int r = 0; r < reps; ++r) {
    double sum = 0, sum2 = 0;
    for (int i = 0; i < n; ++i) {
      const TofSpadKernel kr(cfg, 1, 1, {static_cast<std::uint64_t>(r) * 1000 + i + 1, SpadNoise{}});
      const GroupHistogram g = kr.simulate_group(0, 0, 0, [&](int, int) { return PixelRates{s, b, rt}; });
      double e = 0;
      for (long long v : g.events[0]) e += static_cast<double>(v);
      sum += e, sum2 += e * e;
    }
    const double mean = sum / n, sd = std::sqrt(std::max(0.0, (sum2 - n * mean * mean) / (n - 1)));
    covered += std::fabs(mean - truth) <= t975 * sd / std::sqrt(double(n));
  }
  RecordProperty("covered_of_200", covered);
  EXPECT_GE(covered, 182);
}

// Hazard: photon times were absolute double seconds, so the phase within the laser cycle kept
// only ulp(t) (1.4e-14 s at 100 s). Times are now (laser cycle, offset): a delta echo 1-5 fs past a
// bin edge lands in that bin at any cycle of a 100 s integration (4e9 laser cycles, reached by
// geometric skips), exactly as at t = 0; the absolute form put every photon past 64 s in the bin
// below (counted here as the test's proof of power).
TEST(SpadHazards, PhotonPhaseExactAfterHundredSeconds) {
  TofSpadConfig cfg;
  cfg.spad.dead_time_s = 0;
  cfg.tdc.busy_time_s = 0;
  cfg.tdc.columns_per_tdc = 1;
  cfg.histogram.integration_time_s = 100.0;
  TofSpadKernelOptions o;
  o.noise = SpadNoise::none();  // delta echo, no background: every avalanche is the echo
  const TofSpadKernel k(cfg, 1, 1, o);
  ASSERT_GE(k.laser_cycles(), 4000000000LL);
  // An echo just past a bin edge, placed so that the absolute form rounds it below the edge: in
  // [64 s, 128 s) a double holds multiples of q = 2^-46 s (1.4e-14 s) and cycle x period is on that
  // grid, so the old phase t - cycle x period was the echo offset rounded to a multiple of q.
  const double q = std::ldexp(1.0, -46);
  int code = -1;
  double rt = 0;
  for (int i = 10; i < k.codes() - 10 && code < 0; ++i) {
    const double e = k.bins().edges_s[static_cast<size_t>(i)], below = std::fmod(e, q);
    if (below > 0.1 * q && below < 0.4 * q) code = i, rt = e - below + 0.45 * q;  // e < rt; rt rounds to e - below
  }
  ASSERT_GE(code, 0);
  ASSERT_EQ(k.phase_bin(rt), code);
  const PixelRates r{400.0 / cfg.histogram.integration_time_s, 0, rt};     // ~400 photons over 100 s
  SpadPixelKernel px(cfg, r, o.noise, k.laser_cycles(), o.seed, 0, 0, 0);  // the stream simulate_group uses
  const double period_s = 1.0 / cfg.laser.repetition_rate_Hz;
  long long n = 0, late = 0, off = 0, absolute_off = 0;
  for (; !px.done(); px.pop(), ++n) {
    const SpadTime t = px.peek();
    off += k.phase_bin(t.offset_s) != code;
    late += t.cycle > k.laser_cycles() * 9 / 10;
    // What the absolute form made of it (shows that this test catches the hazard).
    const double t_abs = static_cast<double>(t.cycle) * period_s + t.offset_s;
    const double cycle_abs = std::floor(t_abs / period_s);
    absolute_off += k.phase_bin(t_abs - cycle_abs * period_s) != code;
  }
  EXPECT_GT(n, 300);
  EXPECT_GT(late, 20);  // photons near 90-100 s were checked
  EXPECT_EQ(off, 0);
  EXPECT_GT(absolute_off, n / 5);  // the photons past 64 s, in the absolute form
  // The whole TDC path: every event of the 100 s histogram in that code.
  const GroupHistogram g = k.simulate_group(0, 0, 0, [&](int, int) { return r; });
  long long in_code = g.events[0][code], total = 0;
  for (long long e : g.events[0]) total += e;
  EXPECT_EQ(total, n);
  EXPECT_EQ(in_code, n);
}

}  // namespace
}  // namespace rangesim::systemc::spad
