#include "golden/tof_spad/point_model.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "core/physics.h"
#include "golden/tof_spad/timing_jitter.h"

namespace rangesim::golden::spad {

SpadModel::SpadModel(const TofSpadConfig& cfg)
    : cfg_(cfg),
      bins_(make_tdc_bins(cfg.tdc, 1.0 / cfg.laser.repetition_rate_Hz)),
      cycles_(static_cast<double>(laser_cycles_per_row(cfg)) * cfg.evaluation.frames_averaged),
      share_(tdc_share(cfg.tdc.columns_per_tdc, cfg.tdc.neighbour_rate_fraction)) {}

std::vector<std::pair<std::string, std::string>> SpadModel::reasons() {
  return {
      {"detectable", "range can be derived: enough signal counts, k sigma above the background in the window"},
      {"too_few_signal_counts", "fewer expected signal counts in the peak window than evaluation.min_signal_counts"},
      {"background_dominates", "window signal counts below k sqrt(background counts) (evaluation.detection_sigma)"},
      {"pile_up_saturated", "the TDC is stopped before the echo in nearly every cycle (evaluation.min_armed_fraction)"},
      {"out_of_tdc_range", "the echo falls outside the TDC's codes"}};
}

EstimatorConfig SpadModel::estimator() const {
  return {cfg_.histogram.peak_window_bins, cfg_.histogram.coates_correction, cfg_.histogram.subtract_background};
}

PileUpInput SpadModel::pile_up_input(std::vector<double> r) const {
  PileUpInput in;
  in.photons_per_bin = std::move(r);
  in.codes = bins_.codes;
  in.share = share_;
  const double block_event_s = std::max(cfg_.spad.dead_time_s, cfg_.tdc.busy_time_s);
  in.block_event_bins = static_cast<int>(std::lround(block_event_s / bins_.lsb_s));
  in.block_overflow_bins = static_cast<int>(std::lround(cfg_.spad.dead_time_s / bins_.lsb_s));
  return in;
}

int SpadModel::dead_bins() const { return static_cast<int>(std::lround(cfg_.spad.dead_time_s / bins_.lsb_s)); }

DeadTimeChainInput SpadModel::chain_input(const BinArrivals& ours, const BinArrivals& others) const {
  DeadTimeChainInput in;
  const PileUpInput blocks = pile_up_input({});
  in.codes = bins_.codes;
  in.dead_bins = dead_bins();
  in.block_event_bins = blocks.block_event_bins;
  in.block_overflow_bins = blocks.block_overflow_bins;
  in.share = share_;
  const int m = cfg_.tdc.columns_per_tdc;
  const double f = cfg_.tdc.neighbour_rate_fraction;
  const bool same = ours.total == others.total && ours.signal == others.signal;
  if (m == 1 || f == 0.0 || (f == 1.0 && same)) {
    in.classes.push_back({f == 1.0 ? m : 1, ours.total, ours.signal});
    return in;
  }
  in.classes.push_back({1, ours.total, ours.signal});
  SpadClassArrivals nb{m - 1, others.total, others.signal};
  for (double& x : nb.arrivals) x *= f;
  for (double& x : nb.signal_arrivals) x *= f;
  in.classes.push_back(std::move(nb));
  return in;
}

PileUpHistogram SpadModel::histogram(const Arrivals& a) const { return histogram(a, a); }

PileUpHistogram SpadModel::histogram(const Arrivals& a, const Arrivals& others) const {
  // By recorded time: each SPAD's first photon by its true arrival, its avalanche jittered
  // (timing_jitter.h); the TDC takes the group's first recorded avalanche.
  const BinArrivals arrivals = recorded_arrivals(bins_, a);
  if (dead_bins() >= 1) {
    const DeadTimeChainInput in = chain_input(arrivals, recorded_arrivals(bins_, others));
    if (dead_time_chain_work(in) <= kDeadTimeChainMaxWork) return dead_time_histogram(in);
  }
  std::vector<double> r = arrivals.total;
  for (double& x : r) x *= a.live_fraction;
  PileUpHistogram h = expected_histogram(pile_up_input(std::move(r)));
  if (dead_bins() >= 1)
    h.model = "mean field: SPAD live fraction 1 / (1 + m tau) (dead or busy time too long for the chain)";
  h.background_event_prob.resize(h.event_prob.size());
  for (size_t i = 0; i < h.event_prob.size(); ++i) {
    const double t = arrivals.total[i];
    h.background_event_prob[i] = t > 0 ? h.event_prob[i] * (1 - arrivals.signal[i] / t) : h.event_prob[i];
  }
  return h;
}

PileUpHistogram SpadModel::histogram(double signal_Hz, double background_Hz, double distance_m) const {
  return histogram(make_arrivals(cfg_, signal_Hz, background_Hz, distance_m));
}

PointResult SpadModel::evaluate(double signal_Hz, double background_Hz, double distance_m) const {
  return evaluate(signal_Hz, background_Hz, distance_m, estimator());
}

PointResult SpadModel::evaluate(double signal_Hz, double background_Hz, double distance_m,
                                const EstimatorConfig& est) const {
  const FixedPatternConfig& fp = cfg_.fixed_pattern;
  PointResult p = evaluate_pixel(signal_Hz, background_Hz, distance_m, est, {});
  if (!(fp.prnu_fraction > 0 || fp.dsnu_rms > 0) || !p.moments.defined) return p;
  // The chip: E over the pixels of the mean-square error bias^2 + var. A draw is x = max(floor,
  // sigma z), z standard normal (the kernels clip a gain at 0 and a dark count rate at none): the
  // five-point Gauss-Hermite rule in z (exact for the polynomials up to degree 9; clipped nodes
  // take the floor's pixel). The two spreads' terms add (independent draws, to second order).
  static constexpr std::array<std::pair<double, double>, 5> kNodes{{{0.0, 8.0 / 15},
                                                                    {-1.355626179974266, 0.2220759220056127},
                                                                    {1.355626179974266, 0.2220759220056127},
                                                                    {-2.856970013872806, 0.011257411327720667},
                                                                    {2.856970013872806, 0.011257411327720667}}};
  const auto mse = [](const PointResult& r) { return r.bias_m * r.bias_m + r.std_m * r.std_m; };
  const double mse0 = mse(p);
  double total = mse0;
  const auto spread = [&](double sigma, double floor, auto draw_of) {
    double sum = 0;
    for (const auto& [z, w] : kNodes) {
      if (z == 0.0 && floor < 0) {
        sum += w * mse0;
        continue;
      }
      const PointResult r =
          evaluate_pixel(signal_Hz, background_Hz, distance_m, est, draw_of(std::max(floor, sigma * z)));
      if (!r.moments.defined) return;  // a pixel without an estimate: keep the mean pixel's
      sum += w * mse(r);
    }
    total += sum - mse0;
  };
  if (fp.prnu_fraction > 0) spread(fp.prnu_fraction, -1.0, [](double x) { return PixelDraw{1 + x, 0}; });
  if (fp.dsnu_rms > 0) spread(fp.dsnu_rms, -cfg_.spad.dark_count_rate_Hz, [](double x) { return PixelDraw{1, x}; });
  p.accuracy_m = std::sqrt(std::max(total, 0.0));
  return p;
}

PointResult SpadModel::evaluate_pixel(double signal_Hz, double background_Hz, double distance_m,
                                      const EstimatorConfig& est, const PixelDraw& draw) const {
  // The columns sharing the TDC: their own draws, at the draws' means (a clipped draw's mean is not
  // the nominal: mean of max(floor, sigma z) = floor Phi(floor / sigma) + sigma phi(floor / sigma)).
  const FixedPatternConfig& fp = cfg_.fixed_pattern;
  const auto clipped_mean = [](double sigma, double floor) {
    if (!(sigma > 0)) return 0.0;
    const double z0 = floor / sigma;
    return floor * 0.5 * std::erfc(-z0 / std::sqrt(2.0)) + sigma * std::exp(-0.5 * z0 * z0) / std::sqrt(2 * M_PI);
  };
  const double mean_gain = 1 + clipped_mean(fp.prnu_fraction, -1.0);
  Arrivals others = make_arrivals(cfg_, signal_Hz * mean_gain, background_Hz * mean_gain, distance_m);
  others.uniform_rate_Hz += clipped_mean(fp.dsnu_rms, -cfg_.spad.dark_count_rate_Hz);
  Arrivals a = make_arrivals(cfg_, signal_Hz * draw.gain, background_Hz * draw.gain, distance_m);
  a.uniform_rate_Hz = std::max(0.0, a.uniform_rate_Hz + draw.dark_extra_Hz);
  return evaluate_arrivals(a, others, est, a.round_trip_s);
}

PointResult SpadModel::evaluate_returns(const std::vector<SignalReturn>& returns, double background_Hz,
                                        double truth_m) const {
  Arrivals a = make_arrivals(cfg_, returns.front().signal_Hz, background_Hz, returns.front().distance_m);
  const double f_rep = cfg_.laser.repetition_rate_Hz;
  for (size_t i = 1; i < returns.size(); ++i) {
    const Arrivals more = make_arrivals(cfg_, returns[i].signal_Hz, background_Hz, returns[i].distance_m);
    a.returns.push_back({returns[i].signal_Hz / f_rep, more.round_trip_s});
    a.returns.insert(a.returns.end(), more.returns.begin(), more.returns.end());  // its multipath
  }
  return evaluate_arrivals(a, a, estimator(), 2 * truth_m / phys::kSpeedOfLight_m_per_s);
}

PointResult SpadModel::evaluate_arrivals(const Arrivals& a, const Arrivals& others, const EstimatorConfig& est,
                                         double truth_round_trip_s) const {
  PointResult p;
  p.cycles = cycles_;
  const PileUpHistogram h = histogram(a, others);
  p.chain_converged = h.converged;
  p.detections_per_cycle = h.our_events_per_cycle;
  const int codes = bins_.codes;
  const auto echo_it = std::upper_bound(bins_.edges_s.begin(), bins_.edges_s.end(), a.round_trip_s);
  const int echo = static_cast<int>(std::distance(bins_.edges_s.begin(), echo_it)) - 1;
  if (echo < 0 || echo >= codes) {
    p.detect = "out_of_tdc_range";
    return p;
  }

  // Peak: the largest expected (corrected) bin near the echo. Far from the echo only background
  // competes, which the k-sigma criterion below keeps out of the way.
  auto expected_y = [&](int i) {
    const auto ui = static_cast<size_t>(i);
    if (!est.coates) return h.event_prob[ui];
    return h.armed_prob[ui] * cycles_ >= 1 ? -std::log1p(-std::min(1.0, share_ * h.event_prob[ui] / h.armed_prob[ui]))
                                           : 0.0;
  };
  int peak = echo;
  for (int i = std::max(0, echo - est.peak_window_bins); i <= std::min(codes - 1, echo + est.peak_window_bins); ++i)
    if (expected_y(i) > expected_y(peak)) peak = i;
  p.moments = estimator_moments(h, bins_, cycles_, peak, est);

  // Window counts: our events split by the arrivals' source in each bin.
  const Window w = p.moments.window;
  double window_events = 0, window_background = 0;
  for (int i = w.lo; i <= w.hi; ++i) {
    const auto ui = static_cast<size_t>(i);
    window_events += cycles_ * h.event_prob[ui];
    window_background += cycles_ * h.background_event_prob[ui];
  }
  p.signal_counts = std::max(0.0, window_events - window_background);
  p.background_counts = window_background;
  p.background_per_bin = window_background / (w.hi - w.lo + 1);
  p.armed_at_echo = h.armed_prob[static_cast<size_t>(w.lo)];

  const double half_c = phys::kSpeedOfLight_m_per_s / 2;
  if (p.moments.defined) {
    p.bias_m = half_c * (p.moments.mean_s - truth_round_trip_s);
    p.std_m = half_c * std::sqrt(p.moments.var_s2);
    p.accuracy_m = std::hypot(p.bias_m, p.std_m);
  }
  const auto& e = cfg_.evaluation;
  const double k_sigma_counts = e.detection_sigma * std::sqrt(p.background_counts);
  if (p.armed_at_echo < e.min_armed_fraction)
    p.detect = "pile_up_saturated";
  else if (p.signal_counts < k_sigma_counts && k_sigma_counts >= e.min_signal_counts)
    p.detect = "background_dominates";
  else if (p.signal_counts < e.min_signal_counts || p.signal_counts < k_sigma_counts || !p.moments.defined)
    p.detect = "too_few_signal_counts";
  else
    p.detect = "detectable";
  return p;
}

double afterpulse_armed_fraction(const TofSpadConfig& cfg) {
  const double block_s = std::max(cfg.spad.dead_time_s, cfg.tdc.busy_time_s);
  return cfg.spad.afterpulse_probability *
         std::exp(-(block_s - cfg.spad.dead_time_s) / cfg.spad.afterpulse_time_constant_s);
}

}  // namespace rangesim::golden::spad
