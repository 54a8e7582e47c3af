#include "app/montecarlo/mc_stats.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fmt/format.h>
#include <sstream>
#include <stdexcept>

namespace rangesim::app::mc {

McInterval wilson_interval(long long k, long long n) {
  McInterval r;
  if (n <= 0) return r;
  const double p = static_cast<double>(k) / static_cast<double>(n), nn = static_cast<double>(n);
  const double z2 = kZ95 * kZ95;
  const double centre = (p + z2 / (2 * nn)) / (1 + z2 / nn);
  const double half = kZ95 * std::sqrt(p * (1 - p) / nn + z2 / (4 * nn * nn)) / (1 + z2 / nn);
  r.value = p;
  // At k = 0 (k = n) the interval ends at 0 (1) exactly; the formula leaves a rounding residue.
  r.lo = k == 0 ? 0.0 : std::max(0.0, centre - half);
  r.hi = k == n ? 1.0 : std::min(1.0, centre + half);
  return r;
}

namespace {

// Mean error, std and rms with their intervals of the errors (two passes in trial order: mean,
// then central moments, no cancellation of large sums).
void error_intervals(const std::vector<double>& errors, McInterval* bias, McInterval* std_dev, McInterval& rms) {
  const size_t n = errors.size();
  if (n < 2) return;
  const double nn = static_cast<double>(n);
  double sum = 0, sum_sq = 0;
  for (double e : errors) sum += e, sum_sq += e * e;
  const double mean = sum / nn, ms = sum_sq / nn;
  double m2 = 0, m4 = 0, v_sq = 0;
  for (double e : errors) {
    const double d = e - mean, q = e * e - ms;
    m2 += d * d, m4 += d * d * d * d, v_sq += q * q;
  }
  const double var = m2 / (nn - 1);
  m4 /= nn;
  if (bias) *bias = {mean, mean - kZ95 * std::sqrt(var / nn), mean + kZ95 * std::sqrt(var / nn)};
  const double se_var = std::sqrt(std::max(0.0, m4 - (m2 / nn) * (m2 / nn)) / nn);
  if (std_dev)
    *std_dev = {std::sqrt(var), std::sqrt(std::max(0.0, var - kZ95 * se_var)), std::sqrt(var + kZ95 * se_var)};
  const double se_ms = std::sqrt(v_sq / (nn - 1) / nn);
  rms = {std::sqrt(ms), std::sqrt(std::max(0.0, ms - kZ95 * se_ms)), std::sqrt(ms + kZ95 * se_ms)};
}

}  // namespace

McPointStats summarise_trials(long long trials, const std::vector<double>& errors, const std::vector<char>& outlier) {
  McPointStats s;
  s.trials = trials;
  s.detected = static_cast<long long>(errors.size());
  s.p_detect = wilson_interval(s.detected, trials);
  for (std::size_t i = 0; i < errors.size() && i < outlier.size(); ++i) s.outliers += outlier[i] ? 1 : 0;
  s.p_outlier = wilson_interval(s.outliers, trials);
  error_intervals(errors, &s.bias, &s.std, s.rms);
  if (s.outliers == 0) {  // the clean trials are all of them: the same sums (no copy of 8 MB per 10^6 trials)
    s.rms_clean = s.rms;
    return s;
  }
  std::vector<double> clean;
  clean.reserve(errors.size() - static_cast<std::size_t>(s.outliers));
  for (std::size_t i = 0; i < errors.size(); ++i)
    if (i >= outlier.size() || !outlier[i]) clean.push_back(errors[i]);
  error_intervals(clean, nullptr, nullptr, s.rms_clean);
  return s;
}

std::string McPointStats::to_record() const {
  std::string r = fmt::format("{} {} {}", trials, detected, outliers);
  for (const McInterval* i : {&p_detect, &bias, &std, &rms, &p_outlier, &rms_clean})
    for (double v : {i->value, i->lo, i->hi}) {
      char buf[64];
      std::snprintf(buf, sizeof buf, " %a", v);
      r += buf;
    }
  return r;
}

McPointStats McPointStats::from_record(const std::string& record) {
  std::istringstream in(record);
  McPointStats s;
  if (!(in >> s.trials >> s.detected >> s.outliers))
    throw std::runtime_error("malformed Monte Carlo record: " + record);
  for (McInterval* i : {&s.p_detect, &s.bias, &s.std, &s.rms, &s.p_outlier, &s.rms_clean})
    for (double* v : {&i->value, &i->lo, &i->hi}) {
      std::string tok;
      if (!(in >> tok)) throw std::runtime_error("malformed Monte Carlo record: " + record);
      *v = std::strtod(tok.c_str(), nullptr);  // reads %a hex floats and nan exactly
    }
  return s;
}

}  // namespace rangesim::app::mc
