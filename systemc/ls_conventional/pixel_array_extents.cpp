// The pixel array's exact path, what the latch holds (pixel_array_kernel.h): from the first firings
// drawn at the reset, a row's extent (lowest and highest activated column) at every sampling, which
// is all the event-skipping address search reads, and its bits when row() asks for them. The held
// core ranges are the union of the certain intervals' ranges by sampling k (hold_ranges); a band
// pixel's own first firing decides it, even inside a held range.
#include <algorithm>
#include <cstring>
#include <limits>

#include "systemc/ls_conventional/pixel_array_kernel.h"

namespace rangesim::systemc {

void PixelArrayKernel::hold_ranges(RowShape& s) const {
  // Core ranges are nested (all are |i - x0| <= r_k): their union by k is the widest so far. None:
  // first = INT_MAX, last = -1 (fill_extents widens it without a branch).
  const int N = config_.multisampling.samplings;
  int a = std::numeric_limits<int>::max(), b = -1;
  for (std::size_t k = 0; k < static_cast<std::size_t>(N); ++k) {
    if (s.core_first[k] <= s.core_last[k]) {
      a = std::min(a, s.core_first[k]);
      b = std::max(b, s.core_last[k]);
    }
    s.held_first[k] = a, s.held_last[k] = b;
  }
  s.band_column_from.clear();
  for (const BandPixel& p : s.band) {
    int from = N + 1;
    for (int k = N; k >= 1; --k)
      if (s.held_first[static_cast<std::size_t>(k - 1)] <= p.column && p.column <= s.held_last[static_cast<std::size_t>(k - 1)])
        from = k;
    s.band_column_from.push_back(p.column);
    s.band_column_from.push_back(from);
  }
}

namespace {
// Fired by sampling k: first firing 1..k (0, never, wraps to the largest unsigned).
inline bool fired_by(std::uint8_t first_firing, int k) {
  return static_cast<unsigned>(first_firing) - 1U < static_cast<unsigned>(k);
}
}  // namespace

void PixelArrayKernel::set_row_bits(ActivationRow& act, const RowShape& s, const std::uint8_t* fk, int k) const {
  // What the latch holds at sampling k: the core ranges of samplings 1..k, then each band pixel as
  // its own first firing says (even inside a core range).
  act.clear_to_width(columns());
  if (k == 0) return;
  act.set_range(s.held_first[static_cast<std::size_t>(k - 1)], s.held_last[static_cast<std::size_t>(k - 1)]);
  for (std::size_t j = 0; j < s.band.size(); ++j) act.set(s.band[j].column, fired_by(fk[j], k));
}

void PixelArrayKernel::build_row(int r) const {
  const ExactRun& run = run_of(r);
  const RowShape& s = shapes_[static_cast<std::size_t>(run.shape)];
  std::uint8_t from_key[8];  // a keyed row's first firings: its pattern's key's low bytes (finish_run)
  const std::uint8_t* fk = band_k_.data() + run.band_at + static_cast<std::size_t>(r - run.r0) * s.band.size();
  if (keyed_rows(s)) {
    std::memcpy(from_key, &pattern_key_[row_pattern_[static_cast<std::size_t>(r)]], 8);
    fk = from_key;
  }
  set_row_bits(act_[static_cast<std::size_t>(r)], s, fk, sampling_);
  act_at_[static_cast<std::size_t>(r)] = generation_;
}

namespace {
// fill_extents' widening of one row, N samplings (a compile-time N keeps the k loop in vector
// registers): the held ranges' first / last columns, then each band pixel fired by k. Returns
// whether a band pixel sits in the held range before it fired (a hole).
template <int N>
bool widen_by_band(int n, int* __restrict first, int* __restrict last, const int* __restrict held_first,
                   const int* __restrict held_last, const int* __restrict column_from, const std::uint8_t* fk,
                   std::size_t band) {
  const int samplings = N > 0 ? N : n;
  int f1[N > 0 ? N : 1], l1[N > 0 ? N : 1];
  int* F = N > 0 ? f1 : first;
  int* L = N > 0 ? l1 : last;
  for (int k = 0; k < samplings; ++k) F[k] = held_first[k], L[k] = held_last[k];
  bool hole = false;
  for (std::size_t j = 0; j < band; ++j) {
    const int f = fk[j], c = column_from[2 * j], from = column_from[2 * j + 1];
    hole |= (from <= samplings) & ((f == 0) | (f > from));
    const unsigned f_1 = static_cast<unsigned>(f) - 1U;  // fired by k + 1: f - 1 < k + 1, unsigned
    for (int k = 0; k < samplings; ++k) {
      const bool on = f_1 < static_cast<unsigned>(k + 1);
      F[k] = on && c < F[k] ? c : F[k];
      L[k] = on && c > L[k] ? c : L[k];
    }
  }
  for (int k = 0; k < samplings; ++k) {
    first[k] = L[k] < 0 ? -1 : F[k];
    last[k] = L[k];
  }
  return hole;
}
}  // namespace

void PixelArrayKernel::fill_extents(int r, RowShape& s, const std::uint8_t* fk, std::uint64_t key) {
  // Per sampling: the held core range widened by the band pixels fired by then (without branches on
  // the random first firings: no range is first = INT_MAX, last = -1 here). A band pixel inside the
  // held range that has not fired (its draw fell in a 2^-56 tail of a certain outcome) punches a
  // hole that may be at the range's edge: such a row takes its extents from its bits.
  // The extents are a function of the band's first firings, and the rows of a shape mostly repeat a
  // few patterns of them (two rows in three on the plane map repeat the previous row's). Each call
  // makes the row a new extent pattern of the frame access (extent_patterns), and a small memo per
  // shape keeps it, keyed by the packed first firings (n << 56 | fk[j] << 8 j, n < 8 band pixels;
  // kNoPattern: none), which finish_run assembles as it draws and looks up before it calls this: a
  // row found there shares the pattern, and nothing per sampling is written for it.
  const int N = config_.multisampling.samplings;
  const std::size_t p = patterns_++, at = p * static_cast<std::size_t>(N);
  row_pattern_[static_cast<std::size_t>(r)] = static_cast<std::uint32_t>(p);
  int* first = pattern_first_.data() + at;
  int* last = pattern_last_.data() + at;
  const std::size_t n = s.band.size();
  const int* hf = s.held_first.data();
  const int* hl = s.held_last.data();
  const int* cf = s.band_column_from.data();
  bool hole;
  switch (N) {  // the usual counts of samplings unrolled (the preset's is 4)
    case 2: hole = widen_by_band<2>(N, first, last, hf, hl, cf, fk, n); break;
    case 4: hole = widen_by_band<4>(N, first, last, hf, hl, cf, fk, n); break;
    case 8: hole = widen_by_band<8>(N, first, last, hf, hl, cf, fk, n); break;
    default: hole = widen_by_band<0>(N, first, last, hf, hl, cf, fk, n);
  }
  if (hole) extents_from_bits(first, last, s, fk);
  pattern_key_[p] = key;
  if (key == RowShape::kNoPattern) return;
  const std::size_t slot = RowShape::memo_slot(key);
  s.memo_key[slot] = key;
  s.memo_pattern[slot] = static_cast<std::uint32_t>(p);
}

void PixelArrayKernel::extents_from_bits(int* first, int* last, const RowShape& s, const std::uint8_t* fk) {
  ActivationRow bits(columns());
  for (int k = 1; k <= config_.multisampling.samplings; ++k) {
    set_row_bits(bits, s, fk, k);
    first[k - 1] = bits.first();
    last[k - 1] = bits.last();
  }
}

}  // namespace rangesim::systemc
