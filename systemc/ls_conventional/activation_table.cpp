#include "systemc/ls_conventional/activation_table.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rangesim::systemc {

namespace {
double fourth_derivative_bound(double s) { return ActivationTable::kMaxPhiThirdDerivative / (s * s * s * s); }
}  // namespace

double ActivationTable::intervals_for(double s, double lo, double hi) {
  lo = std::max(lo, 0.0);
  const double h_max = std::pow(384 * kInterpolationTarget / fourth_derivative_bound(s), 0.25);
  return std::max(1.0, std::ceil((std::max(hi, lo) - lo) / h_max));
}

ActivationTable::ActivationTable(double t, double s, double lo, double hi) {
  if (!(s > 0)) throw std::invalid_argument("ActivationTable: needs static noise (sigma_e > 0)");
  if (!(hi >= lo) || !std::isfinite(hi)) throw std::invalid_argument("ActivationTable: needs lambda_lo <= lambda_hi");
  const double n_intervals = intervals_for(s, lo, hi);
  if (!(n_intervals <= kMaxIntervals)) throw std::invalid_argument("ActivationTable: too many intervals");
  lo = std::max(lo, 0.0);
  hi = std::max(hi, lo);
  const double m4 = fourth_derivative_bound(s);
  const int intervals = static_cast<int>(n_intervals);
  lo_e_ = lo;
  step_e_ = hi > lo ? (hi - lo) / intervals : 1.0;
  inv_step_ = 1 / step_e_;
  nodes_ = intervals + 1;
  bound_ = std::pow(step_e_, 4) / 384 * m4 + kNodeAllowance;

  // H(n) = Phi((n - t) / s) over every count the nodes' pmfs reach (their mass beyond the margin
  // of 14 sqrt(lambda) + 40 is below 1e-40).
  const double margin = 14 * std::sqrt(hi) + 40;
  const double n0 = std::max(0.0, std::floor(lo - margin)), n1 = std::ceil(hi + margin);
  std::vector<double> H(static_cast<std::size_t>(n1 - n0) + 2);
  for (std::size_t k = 0; k < H.size(); ++k)
    H[k] = 0.5 * std::erfc(-((n0 + static_cast<double>(k)) - t) / s * M_SQRT1_2);
  const double n_last = n0 + static_cast<double>(H.size()) - 2;  // H(n + 1) exists up to here

  node_.assign(2 * static_cast<std::size_t>(nodes_), 0.0);
  for (int j = 0; j < nodes_; ++j) {
    const double l = lo + j * step_e_;
    double f = 0, fp = 0, total = 0;  // f = E[H(n)], f' = E[H(n + 1) - H(n)]
    auto add = [&](double n, double p) {
      const std::size_t k = static_cast<std::size_t>(n - n0);
      f += p * H[k];
      fp += p * (H[k + 1] - H[k]);
      total += p;
    };
    if (l <= 0) {
      add(0, 1.0);
    } else {
      // The pmf by recurrence outwards from the mode (started in log space), cut where it falls
      // below 1e-20 of the mode's (monotone beyond, so the rest is smaller still).
      const double mode = std::clamp(std::floor(l), n0, n_last);
      const double pm = std::exp(mode * std::log(l) - l - std::lgamma(mode + 1));
      add(mode, pm);
      for (double n = mode, p = pm; n < n_last;) {
        p *= l / (n + 1);
        if (p < 1e-20 * pm) break;
        add(++n, p);
      }
      for (double n = mode, p = pm; n > n0;) {
        p *= n / l;
        if (p < 1e-20 * pm) break;
        add(--n, p);
      }
    }
    // Divided by the summed mass: the pmf's rounding (~1e-13 after hundreds of recurrence steps)
    // would otherwise show where f is close to 1.
    node_[2 * static_cast<std::size_t>(j)] = f / total;
    node_[2 * static_cast<std::size_t>(j) + 1] = step_e_ * fp / total;
  }
}

}  // namespace rangesim::systemc
