#include "golden/tof_spad/timing_jitter.h"

#include <algorithm>
#include <cmath>

namespace rangesim::golden::spad {

namespace {

size_t u(long long i) { return static_cast<size_t>(i); }
double normal_cdf(double x) { return 0.5 * std::erfc(-x / std::sqrt(2.0)); }
// Integral of the normal cdf: F(x) = x Phi(x) + phi(x).
double cdf_integral(double x) { return x * normal_cdf(x) + std::exp(-0.5 * x * x) / std::sqrt(2 * M_PI); }

// Slices of a bin over which an echo's avalanches are taken uniform: the slices' masses are exact
// (erfc), only their insides are flat (the preset's pulse sigma is 0.44 bin: 16 slices).
constexpr int kEchoSlices = 16;
// The jitter's reach: +-12 sigma (beyond, < 1e-32 of it).
constexpr double kReach = 12;

class Spreader {
 public:
  Spreader(const TdcBins& b, double sigma_s) : b_(b), s_(sigma_s), np_(b.phase_bins) {}

  long long phase(long long abs_bin) const { return ((abs_bin % np_) + np_) % np_; }
  double edge(long long abs_edge) const {
    const long long k = (abs_edge - phase(abs_edge)) / np_;
    return static_cast<double>(k) * b_.period_s + b_.edges_s[u(phase(abs_edge))];
  }
  long long bin_of(double t_s) const {
    const double k = std::floor(t_s / b_.period_s);
    const double ph = t_s - k * b_.period_s;
    const long j = std::upper_bound(b_.edges_s.begin(), b_.edges_s.end(), ph) - b_.edges_s.begin() - 1;
    return static_cast<long long>(k) * np_ + std::clamp<long>(j, 0, np_ - 1);
  }

  // `mass` avalanches uniform over [a, b] (a == b: at a point), recorded t + jitter: added to
  // `out` by absolute recorded bin (out[0]: bin `base`).
  void add(double a, double b, double mass, long long base, std::vector<double>& out) const {
    if (!(mass > 0)) return;
    const double w = b - a;
    const auto cdf = [&](double e) {  // P(t + jitter < e), t uniform on [a, b]
      if (w < 1e-6 * s_) return normal_cdf((e - 0.5 * (a + b)) / s_);
      return s_ / w * (cdf_integral((e - a) / s_) - cdf_integral((e - b) / s_));
    };
    const long long lo = bin_of(a - kReach * s_), hi = bin_of(b + kReach * s_);
    const double c_lo = cdf(edge(lo)), norm = cdf(edge(hi + 1)) - c_lo;
    double prev = c_lo;
    for (long long j = lo; j <= hi; ++j) {
      const double c = cdf(edge(j + 1));
      if (j >= base && j - base < static_cast<long long>(out.size()))  // always, by the caller's margins
        out[u(j - base)] += mass * std::max(0.0, c - prev) / norm;
      prev = c;
    }
  }

 private:
  const TdcBins& b_;
  double s_;
  long long np_;
};

// The echoes' photons per cycle in n equal slices of [e0, e1] (erfc; a delta pulse: the slice
// holding its centre), the echoes' centres shifted by `shift` (the period of the bin).
std::vector<double> echo_slices(double e0, double e1, int n, double shift, const std::vector<double>& centre,
                                const std::vector<double>& mass, double pulse_sigma_s) {
  std::vector<double> em(u(n), 0.0);
  const double dw = (e1 - e0) / n, k = 1.0 / (std::sqrt(2.0) * pulse_sigma_s);
  for (int sl = 0; sl < n; ++sl) {
    const double lo = e0 + sl * dw, hi = sl + 1 == n ? e1 : lo + dw;
    for (size_t e = 0; e < centre.size(); ++e) {
      const double c = centre[e] + shift;
      em[u(sl)] += pulse_sigma_s > 0 ? mass[e] * 0.5 * (std::erfc((lo - c) * k) - std::erfc((hi - c) * k))
                                     : (c >= lo && c < hi ? mass[e] : 0.0);
    }
  }
  return em;
}

}  // namespace

BinArrivals recorded_arrivals(const TdcBins& bins, const Arrivals& a) {
  BinArrivals t = bin_arrivals(bins, a);
  if (!(a.jitter_sigma_s > 0)) return t;
  std::vector<double> echo_c, echo_m;
  if (a.signal_per_cycle > 0) echo_c.push_back(a.round_trip_s), echo_m.push_back(a.signal_per_cycle);
  for (const Return& r : a.returns)
    if (r.signal_per_cycle > 0) echo_c.push_back(r.round_trip_s), echo_m.push_back(r.signal_per_cycle);
  // Without an echo the arrivals are uniform: a jittered Poisson process is the same process.
  if (echo_c.empty()) return t;
  const int np = bins.phase_bins;
  double lsb = bins.period_s;  // the narrowest bin: the reaches in bins hold for every bin
  for (int i = 0; i < np; ++i) lsb = std::min(lsb, bins.width_s(i));
  const Spreader sp(bins, a.jitter_sigma_s);
  // The window around the echoes where the first photon matters, with a margin of two jitter
  // reaches on each side: a SPAD live from the window's start has the uniform rate as its hazard
  // again one reach after it, and the survival before the window's end needs no later photon.
  const long long reach = static_cast<long long>(std::ceil(kReach * a.jitter_sigma_s / lsb)) + 1;
  const long long pulse = static_cast<long long>(std::ceil(kReach * a.pulse_sigma_s / lsb)) + 1;
  const long long margin = 2 * reach;
  const long long first = sp.bin_of(*std::min_element(echo_c.begin(), echo_c.end())) - pulse - margin;
  const long long last = sp.bin_of(*std::max_element(echo_c.begin(), echo_c.end())) + pulse + margin;
  if (last - first + 1 > np) {
    // Jitter or pulse of a period: the former approximation, the jitter folded into the pulse.
    Arrivals folded = a;
    folded.pulse_sigma_s = std::hypot(a.pulse_sigma_s, a.jitter_sigma_s);
    return bin_arrivals(bins, folded);
  }
  // A SPAD live from the window's start: its first photon by true time, slice by slice (P =
  // survival x (1 - exp(-m)), the echo's part by its share), and where it is recorded (absolute
  // bins from first - reach).
  const long long base = first - reach, n_local = last - first + 1 + 2 * reach;
  std::vector<double> rec(u(n_local), 0.0), rec_echo(u(n_local), 0.0);
  double surv = 1;
  for (long long j = first; j <= last; ++j) {
    const long long i = sp.phase(j), k_period = (j - i) / np;
    const double shift = static_cast<double>(k_period) * bins.period_s;
    const double e0 = sp.edge(j), e1 = sp.edge(j + 1);
    const double m_bg = t.total[u(i)] - t.signal[u(i)], m_echo = t.signal[u(i)];
    const int n = m_echo > 0 ? kEchoSlices : 1;
    const double dw = (e1 - e0) / n;
    const std::vector<double> em = echo_slices(e0, e1, n, shift, echo_c, echo_m, a.pulse_sigma_s);
    double em_sum = 0;
    for (double x : em) em_sum += x;
    for (int sl = 0; sl < n; ++sl) {
      const double lo = e0 + sl * dw, hi = sl + 1 == n ? e1 : lo + dw;
      const double me = em_sum > 0 ? m_echo * em[u(sl)] / em_sum : (n == 1 ? m_echo : 0.0);
      const double m = m_bg * (hi - lo) / (e1 - e0) + me;
      if (!(m > 0)) continue;
      const double p = surv * -std::expm1(-m), p_echo = p * me / m;
      surv *= std::exp(-m);
      sp.add(lo, hi, p - p_echo, base, rec);
      // A delta pulse's photons are at its centre (one echo; more: over the slice).
      const bool point = !(a.pulse_sigma_s > 0) && echo_c.size() == 1;
      sp.add(point ? echo_c[0] + shift : lo, point ? echo_c[0] + shift : hi, p_echo, base, rec_echo);
    }
  }
  // The hazard inside the margins: r_j = ln(S_j / S_{j+1}), S from the end (sums of positive
  // terms: no cancellation). Outside, the arrivals as they are (uniform there).
  double after = surv;  // S_{j+1}
  for (long long j = base + n_local - 1; j >= base; --j) {
    const double g = rec[u(j - base)] + rec_echo[u(j - base)];
    if (j >= first + margin && j <= last - margin && after > 1e-290) {
      const double r = std::log1p(g / after), share = g > 0 ? std::clamp(rec_echo[u(j - base)] / g, 0.0, 1.0) : 0.0;
      t.total[u(sp.phase(j))] = r, t.signal[u(sp.phase(j))] = r * share;
    }
    after += g;
  }
  return t;
}

}  // namespace rangesim::golden::spad
