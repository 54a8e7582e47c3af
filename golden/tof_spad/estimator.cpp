#include "golden/tof_spad/estimator.h"

#include <algorithm>
#include <cmath>

namespace rangesim::golden::spad {

namespace {

// Linear weights of numerator and denominator: t_hat = sum(alpha_i y_i) / sum(gamma_i y_i) with
// times measured from the peak bin's centre (the centroid is shift invariant; this avoids
// cancellation between 25 ns offsets and ps-scale results).
struct Weights {
  std::vector<double> alpha, gamma;
  double origin_s = 0;
};

// Into k, whose vectors keep their capacity (estimate_time_s runs per pixel: no allocation).
void fill_weights(const TdcBins& bins, int codes, const Window& w, bool subtract, Weights& k) {
  k.alpha.assign(static_cast<size_t>(codes), 0.0);
  k.gamma.assign(static_cast<size_t>(codes), 0.0);
  k.origin_s = bins.centre_s((w.lo + w.hi) / 2);
  const int in = w.hi - w.lo + 1, out = codes - in;
  double t_sum = 0;
  for (int i = w.lo; i <= w.hi; ++i) {
    k.alpha[static_cast<size_t>(i)] = bins.centre_s(i) - k.origin_s;
    k.gamma[static_cast<size_t>(i)] = 1.0;
    t_sum += bins.centre_s(i) - k.origin_s;
  }
  if (subtract && out > 0) {  // b_hat = mean of the bins outside, taken off every window bin
    for (int i = 0; i < codes; ++i) {
      if (i >= w.lo && i <= w.hi) continue;
      k.alpha[static_cast<size_t>(i)] = -t_sum / out;
      k.gamma[static_cast<size_t>(i)] = -static_cast<double>(in) / out;
    }
  }
}

Weights weights(const TdcBins& bins, int codes, const Window& w, bool subtract) {
  Weights k;
  fill_weights(bins, codes, w, subtract, k);
  return k;
}

}  // namespace

Window peak_window(int peak_bin, int pw, int codes) {
  pw = std::max(1, std::min(pw, codes));
  Window w;
  w.lo = peak_bin - pw / 2;
  w.lo = std::max(0, std::min(w.lo, codes - pw));
  w.hi = w.lo + pw - 1;
  return w;
}

void coates_rates(const HistogramCounts& h, std::vector<double>& r) {
  r.assign(h.events.size(), 0.0);
  for (size_t i = 0; i < r.size(); ++i) {
    const double a = h.armed[i];
    if (a <= 0) continue;  // never armed: no information
    const double q = std::min(h.share * h.events[i] / a, 1.0 - 0.5 / a);
    r[i] = -std::log1p(-q) / h.share;
  }
}

std::vector<double> coates_rates(const HistogramCounts& h) {
  std::vector<double> r;
  coates_rates(h, r);
  return r;
}

int peak_bin(const HistogramCounts& h, const EstimatorConfig& cfg) {
  const std::vector<double> y = cfg.coates ? coates_rates(h) : h.events;
  return static_cast<int>(std::max_element(y.begin(), y.end()) - y.begin());
}

std::optional<double> estimate_time_s(const HistogramCounts& h, const TdcBins& bins, const EstimatorConfig& cfg,
                                      int* peak_bin_out) {
  const int codes = static_cast<int>(h.events.size());
  double total = 0;
  for (double e : h.events) total += e;
  if (total <= 0) return std::nullopt;
  // Scratch kept per thread: the clock-level models call this for every pixel of a frame.
  thread_local std::vector<double> rates;
  thread_local Weights k;
  if (cfg.coates) coates_rates(h, rates);
  const std::vector<double>& y = cfg.coates ? rates : h.events;
  const int peak = static_cast<int>(std::max_element(y.begin(), y.end()) - y.begin());
  if (peak_bin_out) *peak_bin_out = peak;
  fill_weights(bins, codes, peak_window(peak, cfg.peak_window_bins, codes), cfg.subtract_background, k);
  double num = 0, den = 0, scale = 0;
  for (int i = 0; i < codes; ++i) {
    num += k.alpha[static_cast<size_t>(i)] * y[static_cast<size_t>(i)];
    den += k.gamma[static_cast<size_t>(i)] * y[static_cast<size_t>(i)];
    scale += std::fabs(k.gamma[static_cast<size_t>(i)] * y[static_cast<size_t>(i)]);
  }
  // Nothing above the background in the window (up to rounding of the subtraction).
  if (!(den > 1e-9 * scale)) return std::nullopt;
  return k.origin_s + num / den;
}

EstimateMoments estimator_moments(const PileUpHistogram& h, const TdcBins& bins, double cycles, int peak_bin,
                                  const EstimatorConfig& cfg) {
  const int codes = static_cast<int>(h.event_prob.size());
  EstimateMoments m;
  m.peak_bin = peak_bin;
  m.window = peak_window(peak_bin, cfg.peak_window_bins, codes);
  const Weights k = weights(bins, codes, m.window, cfg.subtract_background);
  double mu_n = 0, mu_d = 0;
  // Second moments: diagonal part, and (raw counts) the multinomial rank-one part.
  double vnn = 0, vdd = 0, vnd = 0, an = 0, ad = 0;
  const double s = h.share;
  for (int i = 0; i < codes; ++i) {
    const auto ui = static_cast<size_t>(i);
    const double a = k.alpha[ui], g = k.gamma[ui];
    double mean = 0, var = 0;
    if (cfg.coates) {
      // What Coates reads from our counts: s x our events per armed cycle (the group's hazard
      // when every column sees our rates; the estimator assumes that, PileUpHistogram need not).
      const double armed = cycles * h.armed_prob[ui];
      const double q = h.armed_prob[ui] > 0 ? std::min(1.0, s * h.event_prob[ui] / h.armed_prob[ui]) : 0.0;
      // coates_rates caps q at 1 - 1/(2A): a bin that stops (nearly) every armed cycle reads
      // ln(2A)/s whatever the rate. Without the cap here a hazard that rounds to 1 (s r > 37,
      // count rates far above 1/dead time) read as an empty bin and lost the echo.
      const double q_cap = armed >= 1 ? 1 - 0.5 / armed : 0;
      if (armed >= 1 && q >= q_cap) {
        mean = std::log(2 * armed) / s;
      } else if (armed >= 1) {
        const double var_q = s * q * (1 - q / s) / armed;  // binomial, s x our counts / armed
        var = var_q / (s * s * (1 - q) * (1 - q));
        mean = -std::log1p(-q) / s + 0.5 * s * var;
        // The capped estimate lies in [0, ln(2A)/s]: its mean and variance cannot exceed that
        // (the delta method's (1-q)^-2 blows up next to the cap).
        const double top = std::log(2 * armed) / s;
        mean = std::min(mean, top);
        var = std::min(var, 0.25 * top * top);
      }
    } else {
      mean = cycles * h.event_prob[ui];
      var = mean;
      an += a * mean, ad += g * mean;  // multinomial: - N p_i p_j = - mean_i mean_j / N
    }
    mu_n += a * mean, mu_d += g * mean;
    vnn += a * a * var, vdd += g * g * var, vnd += a * g * var;
  }
  if (!cfg.coates && cycles > 0) {
    vnn -= an * an / cycles, vdd -= ad * ad / cycles, vnd -= an * ad / cycles;
  }
  if (!(mu_d > 0)) return m;
  m.defined = true;
  const double ratio = mu_n / mu_d;
  // Divide twice: mu_d^2 underflows to 0 (inf) for window sums below 1e-154 (a TDC stopped
  // before the echo in all but 1e-160 of the cycles).
  m.mean_s = k.origin_s + ratio + (ratio * vdd - vnd) / mu_d / mu_d;
  m.var_s2 = std::max(0.0, vnn - 2 * ratio * vnd + ratio * ratio * vdd) / mu_d / mu_d;
  return m;
}

double thompson_sigma_t_s(double s, double a, double n, double b) {
  if (!(n > 0)) return INFINITY;
  return std::sqrt((s * s + a * a / 12) / n + 4 * std::sqrt(M_PI) * s * s * s * b / (a * n * n));
}

}  // namespace rangesim::golden::spad
