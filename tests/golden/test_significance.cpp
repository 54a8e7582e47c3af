// The significance arithmetic behind every range map's validity flag (golden/common/significance.h):
// Poisson tails against closed forms, and the Gaussian-equivalent sigma against Q(z).
#include <gtest/gtest.h>

#include <cmath>

#include "golden/common/significance.h"

using rangesim::golden::poisson_upper_tail_log;
using rangesim::golden::sigma_from_log_p;

TEST(Significance, PoissonTailMatchesClosedForms) {
  EXPECT_EQ(poisson_upper_tail_log(0, 3.0), 0.0);
  EXPECT_NEAR(std::exp(poisson_upper_tail_log(1, 0.7)), 1 - std::exp(-0.7), 1e-14);
  // P(X >= 3; 2) = 1 - e^-2 (1 + 2 + 2)
  EXPECT_NEAR(std::exp(poisson_upper_tail_log(3, 2.0)), 1 - 5 * std::exp(-2.0), 1e-14);
  // Far tail: P(X >= 40; 1) = e^-1 / 40! (1 + 1/41 + 1/(41 42) + ...).
  double series = 0, term = 1;
  for (int k = 41; k < 80; ++k) series += term, term /= k;
  EXPECT_NEAR(poisson_upper_tail_log(40, 1.0), -1 - std::lgamma(41.0) + std::log(series), 1e-12);
  // e^-lambda underflows: the normal limit, 1/2 at the mean.
  EXPECT_NEAR(std::exp(poisson_upper_tail_log(1000000, 1000000.5)), 0.5, 1e-3);
}

TEST(Significance, SigmaInvertsTheNormalTail) {
  for (double z : {-2.0, 0.0, 1.0, 3.0, 5.0, 12.0, 30.0})
    EXPECT_NEAR(sigma_from_log_p(std::log(0.5 * std::erfc(z / std::sqrt(2.0)))), z, 1e-9) << z;
  EXPECT_EQ(sigma_from_log_p(-1e6), 38.0);  // capped
}
