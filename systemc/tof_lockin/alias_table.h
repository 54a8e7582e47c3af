#pragma once
// Discrete laws drawn by Walker's alias method (A. J. Walker, "An efficient method for generating
// discrete random variables with general distributions", ACM TOMS 3(3), 1977; table built by
// M. D. Vose's algorithm, "A linear algorithm for generating random numbers with a given
// distribution", IEEE TSE 17(9), 1991): one 64-bit word, one multiply, two table reads and a
// compare per draw, no transcendental call and no rejection. Worth it where many draws share a
// law (a Monte Carlo point's trials, the pixels of a uniform scene).
//
// The word's top bits (times the table size) pick the bucket and the remainder, uniform to
// 2^-64 x size, decides between the bucket and its alias. The table is built in integers: each
// bucket's share in units of 2^-shift of a bucket (the counts are differences of the rounded
// cumulative sums of the pmf, so they add up exactly and each is within a unit of its share;
// one unit is below 2^-62 of the total), and Vose's top-ups are exact. So every value's
// probability is the given pmf to 2^-62 plus the pmf's own rounding (AliasTable.*, PoissonAlias.*
// in tests/skipping/test_lockin_draws.cpp read the probabilities back out of the table).
//
// PoissonAlias: the Poisson law of one mean, the pmf from k_lo to k_hi, cut where the mass left
// out on each side is below 2^-66 by a geometric bound on the pmf's ratios (p(k+1)/p(k) = mu/(k+1)
// falls above the mode, p(k-1)/p(k) = k/mu below it). A table of ~19 sqrt(mean) entries costs
// about as much to build as a few hundred PTRS draws (systemc/common/poisson_sampler.h).
#include <cstdint>
#include <vector>

namespace rangesim::systemc::lockin {

class AliasTable {
 public:
  AliasTable() = default;
  // Values first, first + 1, ... with probabilities proportional to pmf (normalised here).
  AliasTable(const std::vector<double>& pmf, long long first);

  template <class Stream>
  long long operator()(Stream& s) const {
    const unsigned __int128 p = static_cast<unsigned __int128>(s.next()) * size_;
    const auto i = static_cast<std::uint32_t>(p >> 64);
    // Both candidates read, then selected without a branch: the compare is a coin toss where the
    // bucket is shared, and a mispredicted jump cost more than the draw (tof-lockin Monte Carlo).
    const std::uint32_t alias = alias_[i];
    const std::uint64_t keep = 0 - static_cast<std::uint64_t>(static_cast<std::uint64_t>(p) < threshold_[i]);
    return first_ + static_cast<long long>((i & keep) | (alias & ~keep));
  }

  long long first() const { return first_; }
  long long last() const { return first_ + size_ - 1; }
  // The probability the table gives each value first() .. last() (read back from the buckets; for tests).
  std::vector<long double> probabilities() const;

 private:
  long long first_ = 0;
  std::uint32_t size_ = 0;
  std::vector<std::uint64_t> threshold_;  // keep bucket i when the remainder is below this
  std::vector<std::uint32_t> alias_;
};

// The Poisson pmf of `mean` over the counts where it matters: p[i] = P(first + i); the mass left
// out on each side is below 2^-66 (mass_left_out: the bound). Anchored on the log pmf every 128
// ratio steps, so rounding builds up over 128 steps at most (~1e-14).
struct PoissonWindow {
  long long first = 0;
  std::vector<double> p;
  double mass_left_out = 0;
};
PoissonWindow poisson_window(double mean);

class PoissonAlias : public AliasTable {
 public:
  // Means above this use PTRS instead (a table of ~20 sqrt(mean) entries would exceed a few MB).
  static constexpr double kMaxMean = 1e8;
  explicit PoissonAlias(double mean) : PoissonAlias(mean, poisson_window(checked(mean))) {}
  double mean() const { return mean_; }
  // Upper bound of the Poisson mass outside [first, last].
  double mass_left_out() const { return left_out_; }

 private:
  PoissonAlias(double mean, const PoissonWindow& w)
      : AliasTable(w.p, w.first), mean_(mean), left_out_(w.mass_left_out) {}
  static double checked(double mean);
  double mean_;
  double left_out_;
};

}  // namespace rangesim::systemc::lockin
