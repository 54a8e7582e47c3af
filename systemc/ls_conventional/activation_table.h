#pragma once
// The activation probability of one comparator threshold as a table, so that an uncertain pixel's
// first firing sampling can be drawn by inversion with one uniform (activation_sampler.h).
//
// f(lambda) = P(n + R >= t), n ~ Poisson(lambda) electrons, R ~ Normal(0, s^2) the static noise
// (kTC + read) in electrons, t the threshold in electrons: golden::activation_probability without
// its early exits. Nodes every h electrons over [lambda_lo, lambda_hi] hold f and f' (summed here
// over the Poisson pmf, by recurrence from the mode), and a cubic Hermite interpolant joins them.
//
// The stated bound (tested in tests/skipping/test_inversion_draw.cpp against golden at every node
// and between them): |f~(lambda) - f(lambda)| <= bound() for lambda in [lambda_lo, lambda_hi], with
//   bound = h^4 / 384 * M4 + kNodeAllowance,   M4 = 0.5506 / s^4 >= sup |f''''|.
// h^4 / 384 max|f''''| is the cubic Hermite remainder. For M4: d/dlambda E[g(n)] = E[g(n+1) - g(n)]
// for n ~ Poisson(lambda), so f'''' = E[Delta^4 H(n)] with H(x) = Phi((x - t) / s), and a fourth
// forward difference of unit step is H''''(xi) = phi'''(z) / s^4 for some xi; max |phi'''| =
// max |(z^3 - 3 z) phi(z)| = 0.55059 (at z = 0.742). kNodeAllowance (1e-11) covers the rounding of
// the node sums (< 1e-12 from golden, tested) and golden's own error (< 1e-15). h is chosen so that the
// interpolation part is at most 1e-5 (so the exact fallback runs for ~2e-5 of the comparisons: a
// dozen per map, against half as many nodes to sum as at 1e-6).
// No table is made without static noise (s = 0: H is a step, M4 unbounded); the caller draws those
// pixels another way.
#include <vector>

namespace rangesim::systemc {

class ActivationTable {
 public:
  static constexpr double kMaxPhiThirdDerivative = 0.55059;  // max |(z^3 - 3 z) phi(z)|, rounded up
  static constexpr double kInterpolationTarget = 1e-5;       // h^4 / 384 M4 at most this
  static constexpr double kNodeAllowance = 1e-11;            // node rounding + golden's error

  static constexpr double kMaxIntervals = 65536;  // larger tables are not made

  // Intervals of step <= the largest that meets kInterpolationTarget over [lo, hi] (electrons).
  static double intervals_for(double sigma_e, double lambda_lo_e, double lambda_hi_e);
  // f on [lambda_lo_e, lambda_hi_e] at threshold t_e with static noise s_e > 0 (all in electrons);
  // at most kMaxIntervals intervals.
  ActivationTable(double threshold_e, double sigma_e, double lambda_lo_e, double lambda_hi_e);

  // The interpolated f at lambda (clamped to the table's range).
  double value(double lambda_e) const {
    double x = (lambda_e - lo_e_) * inv_step_;
    if (x < 0) x = 0;
    int j = static_cast<int>(x);
    if (j >= nodes_ - 1) j = nodes_ - 2;
    x -= j;
    const double* n = &node_[2 * static_cast<std::size_t>(j)];  // f_j, h f'_j, f_j+1, h f'_j+1
    const double y = 1 - x, x2 = x * x, y2 = y * y;
    return (1 + 2 * x) * y2 * n[0] + x * y2 * n[1] + x2 * (3 - 2 * x) * n[2] - x2 * y * n[3];
  }
  double bound() const { return bound_; }
  double step_e() const { return step_e_; }
  int nodes() const { return nodes_; }
  double lo_e() const { return lo_e_; }
  double hi_e() const { return lo_e_ + step_e_ * (nodes_ - 1); }
  // f at node j as summed here (for the tests).
  double node_value(int j) const { return node_[2 * static_cast<std::size_t>(j)]; }

 private:
  double lo_e_ = 0, step_e_ = 1, inv_step_ = 1, bound_ = 0;
  int nodes_ = 2;
  std::vector<double> node_;  // per node: f, h f'
};

}  // namespace rangesim::systemc
