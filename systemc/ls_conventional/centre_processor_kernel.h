#pragma once
// Cycle kernel of one row's centre processor (ls-conventional, row-parallel): plain C++.
//
// It listens to its row's address search: every cycle with addr_valid it shifts in addr_bit
// (left address, then right, MSB first, address_bits each); after the 2 B bits of one sampling it
// adds (left + right) to an accumulator and counts the sampling as a detection. Samplings without
// an activated pixel stream nothing and are not counted. The centre of the frame access is the
// mean over the detecting samplings of (left + right) / 2 (golden/ls_conventional/multisampling.h):
//   centre = sum / (2 n)                          (n = 0: no detection, valid = 0)
// Output format: unsigned fixed point Q(address_bits).8 (kCentreFractionBits = 8), rounded to
// nearest with ties up: centre_q = floor((sum * 2^8 + n) / (2 n)); centre_px = centre_q / 256.
// The exact pair (sum, n) is an output too, so tests can require sum / (2 n) == the golden double.
// The accumulator is cleared in every cycle with clear (the sequencer's reset phase).
#include <array>
#include <cstdint>

#include "systemc/common/address_search_kernel.h"

namespace rangesim::systemc {

inline constexpr int kCentreFractionBits = 8;

struct CentreProcessorPins {
  bool valid = false;          // n > 0
  std::uint32_t centre_q = 0;  // Q(address_bits).8 centre, 0 when !valid
  std::uint32_t sum = 0;       // sum of (left + right) over the detecting samplings
  int count = 0;               // n: detecting samplings
  double centre_px() const { return static_cast<double>(centre_q) / (1 << kCentreFractionBits); }
  // The exact centre, sum / (2 n).
  double exact_centre_px() const { return count > 0 ? static_cast<double>(sum) / (2.0 * count) : 0.0; }
  bool operator==(const CentreProcessorPins& o) const {
    return valid == o.valid && centre_q == o.centre_q && sum == o.sum && count == o.count;
  }
  bool operator!=(const CentreProcessorPins& o) const { return !(*this == o); }
};

// floor(x / (2 n)) as the high half of x m_n for the counts a sensor can have (samplings <= 64):
// m_n = floor((2^64 - 1) / (2 n)) + 1 exceeds 2^64 / (2 n) by e / (2 n) with 0 <= e <= 2 n <= 128, so
// x m_n / 2^64 exceeds x / (2 n) by under 1 / (2 n) for every x < 2^56 (here x < 2^41), which
// leaves the floor unchanged. m_0 = 0.
inline constexpr int kReciprocals = 65;
inline constexpr std::array<std::uint64_t, kReciprocals> kReciprocal = [] {
  std::array<std::uint64_t, kReciprocals> m{};
  for (int n = 1; n < kReciprocals; ++n) m[n] = ~std::uint64_t{0} / (2 * static_cast<std::uint64_t>(n)) + 1;
  return m;
}();

class CentreProcessorKernel {
 public:
  explicit CentreProcessorKernel(int address_bits);

  // One rising edge with the inputs of the ending cycle: the row's search pins and clear.
  void tick(bool clear, const AddressSearchPins& search);
  // Event-skipping path: the whole stream of one sampling at once (tests prove it equal).
  void accumulate(const AddressSearchResult& result) {
    // Inline and without a branch: called for every row at every sampling.
    sum_ += result.found ? static_cast<std::uint32_t>(result.left + result.right) : 0U;
    count_ += result.found ? 1 : 0;
  }
  // accumulate() of several results at once: their sum of (left + right) over the found ones and
  // how many were found.
  void accumulate_total(std::uint32_t sum, int found) {
    sum_ += sum;
    count_ += found;
  }
  void clear() { sum_ = 0, count_ = 0, shift_ = 0, bits_ = 0; }

  // Inline and without a branch on the count (read for every row of every frame; near the
  // threshold the count changes at random from row to row, and a switch on it mispredicted).
  CentreProcessorPins pins() const {
    CentreProcessorPins p;
    p.sum = sum_;
    p.count = count_;
    p.valid = count_ > 0;
    const std::uint64_t num =
        (static_cast<std::uint64_t>(sum_) << kCentreFractionBits) + static_cast<std::uint64_t>(count_);
    // floor((sum 2^8 + n) / (2 n)); 0 when n = 0 (the table's first entry)
    p.centre_q = static_cast<std::uint32_t>(count_ < kReciprocals
                                                ? (static_cast<unsigned __int128>(num) * kReciprocal[count_]) >> 64
                                                : num / (2 * static_cast<std::uint64_t>(count_)));
    return p;
  }
  int address_bits() const { return address_bits_; }

 private:
  int address_bits_;         // B
  std::uint32_t sum_ = 0;    // accumulated left + right
  int count_ = 0;            // detecting samplings
  std::uint64_t shift_ = 0;  // bits of the current stream
  int bits_ = 0;             // how many of them
};

}  // namespace rangesim::systemc
