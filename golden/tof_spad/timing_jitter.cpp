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
// Beyond this reach in bins the bins' INL is nothing against the jitter: one kernel on nominal
// bins for all source bins (a circular convolution) instead of a spread per source bin.
constexpr double kMaxExactReachBins = 64;
// Jitter above this many periods: the recorded phase is uniform (the wrapped Gaussian's ripple
// is exp(-2 pi^2 sigma^2 / T^2) < 1e-19).
constexpr double kUniformPeriods = 1.5;

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
  // `out` by recorded phase bin (wrapped over the period).
  void add(double a, double b, double mass, std::vector<double>& out) const {
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
      out[u(phase(j))] += mass * std::max(0.0, c - prev) / norm;
      prev = c;
    }
  }

  // Wide jitter: one kernel on nominal bins, P(recorded d bins later, wrapped), d = 0 .. Np-1.
  std::vector<double> nominal_kernel() const {
    std::vector<double> kern(u(np_), 1.0 / static_cast<double>(np_));
    if (s_ > kUniformPeriods * b_.period_s) return kern;
    std::fill(kern.begin(), kern.end(), 0.0);
    const double lsb = b_.period_s / static_cast<double>(np_);
    const auto cdf = [&](double e) { return s_ / lsb * (cdf_integral(e / s_) - cdf_integral((e - lsb) / s_)); };
    const long long reach = static_cast<long long>(std::ceil(kReach * s_ / lsb)) + 1;
    double prev = cdf(static_cast<double>(-reach) * lsb), sum = 0;
    for (long long d = -reach; d <= reach; ++d) {
      const double c = cdf(static_cast<double>(d + 1) * lsb), p = std::max(0.0, c - prev);
      kern[u(phase(d))] += p, sum += p;
      prev = c;
    }
    for (double& x : kern) x /= sum;
    return kern;
  }

  bool exact() const { return kReach * s_ <= kMaxExactReachBins * b_.period_s / np_; }

 private:
  const TdcBins& b_;
  double s_;
  long long np_;
};

}  // namespace

BinArrivals recorded_arrivals(const TdcBins& bins, const Arrivals& a) {
  BinArrivals t = bin_arrivals(bins, a);
  if (!(a.jitter_sigma_s > 0)) return t;
  const int np = bins.phase_bins;
  const Spreader sp(bins, a.jitter_sigma_s);
  const bool exact = sp.exact();
  std::vector<double> echo_c{a.round_trip_s}, echo_m{a.signal_per_cycle};
  for (const Return& r : a.returns) echo_c.push_back(r.round_trip_s), echo_m.push_back(r.signal_per_cycle);
  // A live SPAD's first photon of the period by true time, slice by slice (P = survival x
  // (1 - exp(-m))), its echo part, and where they are recorded.
  std::vector<double> rec(u(np), 0.0), rec_echo(u(np), 0.0), first(u(np), 0.0), first_echo(u(np), 0.0);
  double surv = 1;
  for (int i = 0; i < np; ++i) {
    const double e0 = bins.edges_s[u(i)], e1 = bins.edges_s[u(i) + 1];
    const double m_bg = t.total[u(i)] - t.signal[u(i)], m_echo = t.signal[u(i)];
    const bool sliced = exact && m_echo > 0;
    const int n = sliced ? kEchoSlices : 1;
    const double dw = (e1 - e0) / n, k = a.pulse_sigma_s > 0 ? 1.0 / (std::sqrt(2.0) * a.pulse_sigma_s) : 0.0;
    // The echo's mass per slice (exact, erfc), scaled to the bin's.
    std::vector<double> em(u(n), 0.0);
    double em_sum = 0;
    for (int sl = 0; sl < n && m_echo > 0; ++sl) {
      const double lo = e0 + sl * dw, hi = sl + 1 == n ? e1 : lo + dw;
      for (size_t e = 0; e < echo_c.size(); ++e) {
        const double c = echo_c[e];
        em[u(sl)] += a.pulse_sigma_s > 0 ? echo_m[e] * 0.5 * (std::erfc((lo - c) * k) - std::erfc((hi - c) * k))
                                         : (c >= lo && c < hi ? echo_m[e] : 0.0);
      }
      em_sum += em[u(sl)];
    }
    for (int sl = 0; sl < n; ++sl) {
      const double lo = e0 + sl * dw, hi = sl + 1 == n ? e1 : lo + dw;
      const double me = em_sum > 0 ? m_echo * em[u(sl)] / em_sum : (n == 1 ? m_echo : 0.0);
      const double mb = m_bg * (hi - lo) / (e1 - e0), m = mb + me;
      if (!(m > 0)) continue;
      const double p = surv * -std::expm1(-m), p_echo = p * me / m;
      surv *= std::exp(-m);
      if (!exact) {
        first[u(i)] += p, first_echo[u(i)] += p_echo;
        continue;
      }
      sp.add(lo, hi, p - p_echo, rec);
      // A delta pulse's photons are at its centre (one echo per bin; more: the slice).
      const bool point = !(a.pulse_sigma_s > 0) && echo_c.size() == 1;
      sp.add(point ? echo_c[0] : lo, point ? echo_c[0] : hi, p_echo, rec_echo);
    }
  }
  if (!exact) {  // wide jitter: one kernel on nominal bins
    const std::vector<double> kern = sp.nominal_kernel();
    for (int i = 0; i < np; ++i) {
      if (!(first[u(i)] > 0)) continue;
      for (int d = 0; d < np; ++d) {
        rec[u((i + d) % np)] += (first[u(i)] - first_echo[u(i)]) * kern[u(d)];
        rec_echo[u((i + d) % np)] += first_echo[u(i)] * kern[u(d)];
      }
    }
  }
  for (int j = 0; j < np; ++j) rec[u(j)] += rec_echo[u(j)];
  // The hazard: r_j = ln(S_j / S_{j+1}), S from the end (sums of positive terms: no
  // cancellation). Where the survival has underflowed the arrivals themselves (no echo there).
  double after = surv;  // S_{j+1}
  for (int j = np - 1; j >= 0; --j) {
    const double g = rec[u(j)];
    if (after > 1e-290 && g >= 0) {
      const double r = std::log1p(g / after), share = g > 0 ? std::clamp(rec_echo[u(j)] / g, 0.0, 1.0) : 0.0;
      t.total[u(j)] = r, t.signal[u(j)] = r * share;
    }
    after += g;
  }
  return t;
}

}  // namespace rangesim::golden::spad
