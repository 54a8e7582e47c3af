#pragma once
// Two-sample statistics that decide "statistically indistinguishable" in the bench and in the
// aggregation tests: difference of means and of variances in standard errors, and the two-sample
// Kolmogorov-Smirnov test (asymptotic p-value, Kolmogorov's series). Header-only, plain C++.
#include <algorithm>
#include <cmath>
#include <vector>

namespace rangesim::app::bench {

struct SampleMoments {
  double n = 0, mean = 0, var = 0, m4 = 0;  // var unbiased; m4 central fourth moment
};

inline SampleMoments moments(const std::vector<double>& x) {
  SampleMoments m;
  m.n = static_cast<double>(x.size());
  for (double v : x) m.mean += v;
  m.mean /= m.n;
  double s2 = 0, s4 = 0;
  for (double v : x) {
    const double d = (v - m.mean) * (v - m.mean);
    s2 += d;
    s4 += d * d;
  }
  m.var = s2 / (m.n - 1);
  m.m4 = s4 / m.n;
  return m;
}

struct TwoSampleComparison {
  double mean_a = 0, mean_b = 0, var_a = 0, var_b = 0;
  double mean_z = 0;  // (mean_a - mean_b) / its standard error
  double var_z = 0;   // (var_a - var_b) / its standard error (from the fourth moments)
  double ks_d = 0;    // sup |F_a - F_b|
  double ks_p = 0;    // asymptotic p-value of ks_d
  // Indistinguishable: |mean_z| < 5, |var_z| < 5 and KS p >= 0.001.
  bool indistinguishable() const { return std::fabs(mean_z) < 5 && std::fabs(var_z) < 5 && ks_p >= 1e-3; }
};

// Q_KS(lambda) = 2 sum (-1)^(j-1) exp(-2 j^2 lambda^2).
inline double kolmogorov_q(double lambda) {
  if (lambda < 0.2) return 1.0;
  double q = 0;
  for (int j = 1; j <= 100; ++j) q += 2 * ((j % 2) ? 1 : -1) * std::exp(-2.0 * j * j * lambda * lambda);
  return std::clamp(q, 0.0, 1.0);
}

inline TwoSampleComparison compare_samples(std::vector<double> a, std::vector<double> b) {
  TwoSampleComparison c;
  const SampleMoments ma = moments(a), mb = moments(b);
  c.mean_a = ma.mean, c.mean_b = mb.mean, c.var_a = ma.var, c.var_b = mb.var;
  const double se_mean = std::sqrt(ma.var / ma.n + mb.var / mb.n);
  c.mean_z = se_mean > 0 ? (ma.mean - mb.mean) / se_mean : (ma.mean == mb.mean ? 0 : INFINITY);
  // var(s^2) ~ (m4 - sigma^4 (n - 3) / (n - 1)) / n
  const double va = (ma.m4 - ma.var * ma.var * (ma.n - 3) / (ma.n - 1)) / ma.n;
  const double vb = (mb.m4 - mb.var * mb.var * (mb.n - 3) / (mb.n - 1)) / mb.n;
  const double se_var = std::sqrt(std::max(0.0, va) + std::max(0.0, vb));
  c.var_z = se_var > 0 ? (ma.var - mb.var) / se_var : (ma.var == mb.var ? 0 : INFINITY);
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  std::size_t i = 0, j = 0;
  double d = 0;
  while (i < a.size() && j < b.size()) {
    const double x = std::min(a[i], b[j]);
    while (i < a.size() && a[i] == x) ++i;
    while (j < b.size() && b[j] == x) ++j;
    d = std::max(d, std::fabs(static_cast<double>(i) / a.size() - static_cast<double>(j) / b.size()));
  }
  c.ks_d = d;
  const double ne = ma.n * mb.n / (ma.n + mb.n);
  c.ks_p = kolmogorov_q((std::sqrt(ne) + 0.12 + 0.11 / std::sqrt(ne)) * d);
  return c;
}

}  // namespace rangesim::app::bench
