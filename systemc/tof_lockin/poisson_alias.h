#pragma once
// Poisson counts of one fixed mean by Walker's alias method (A. J. Walker, "An efficient method for
// generating discrete random variables with general distributions", ACM TOMS 3(3), 1977; table
// built by M. D. Vose's stable algorithm, "A linear algorithm for generating random numbers with a
// given distribution", IEEE TSE 17(9), 1991): one 64-bit word, one multiply, two table reads and a
// compare per count, no transcendental call and no rejection. Worth it where many counts share a
// mean (a Monte Carlo point's trials, the pixels of a uniform scene): building a table costs about
// as much as a few hundred PTRS draws (systemc/common/poisson_sampler.h).
//
// The table holds the pmf from k_lo to k_hi, cut where the mass left out on each side is below
// 2^-66 by a geometric bound on the pmf's ratios (p(k+1)/p(k) = mu/(k+1) falls above the mode,
// p(k-1)/p(k) = k/mu below it), and renormalised. The word's top bits (times the table size) pick
// the bucket and the remainder, uniform to 2^-64 / size, decides between the bucket and its alias.
// So every count's probability is the Poisson pmf to within the double rounding of the pmf
// itself plus 2^-63 (PoissonAlias.* in tests/skipping/test_lockin_draws.cpp read the probabilities
// back out of the table and sample against the pmf).
#include <cstdint>
#include <vector>

namespace rangesim::systemc::lockin {

class PoissonAlias {
 public:
  // Means above this use PTRS instead (a table of ~20 sqrt(mean) entries would exceed a few MB).
  static constexpr double kMaxMean = 1e8;
  explicit PoissonAlias(double mean);

  template <class Stream>
  long long operator()(Stream& s) const {
    const unsigned __int128 p = static_cast<unsigned __int128>(s.next()) * size_;
    const auto i = static_cast<std::uint32_t>(p >> 64);
    return first_ + (static_cast<std::uint64_t>(p) < threshold_[i] ? i : alias_[i]);
  }

  double mean() const { return mean_; }
  long long first() const { return first_; }
  long long last() const { return first_ + size_ - 1; }
  // Upper bound of the Poisson mass outside [first, last].
  double mass_left_out() const { return left_out_; }
  // The probability the table gives each count first() .. last() (read back from the buckets; for tests).
  std::vector<long double> probabilities() const;

 private:
  double mean_;
  long long first_ = 0;
  std::uint32_t size_ = 1;
  double left_out_ = 0;
  std::vector<std::uint64_t> threshold_;  // keep bucket i when the remainder is below this
  std::vector<std::uint32_t> alias_;
};

}  // namespace rangesim::systemc::lockin
