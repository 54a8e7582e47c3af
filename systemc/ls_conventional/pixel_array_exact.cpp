// The pixel array's exact path (pixel_array_kernel.h, activation_sampler.h): each window pixel's
// first firing sampling decided at the reset, certain ones without a draw; with certain intervals
// (certain_intervals.h) only the band between them is looked at one by one.
#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include "golden/common/pixel.h"
#include "golden/common/spot.h"
#include "systemc/common/keyed_uniforms.h"
#include "systemc/common/random_stream.h"
#include "systemc/ls_conventional/pixel_array_kernel.h"

namespace rangesim::systemc {

void PixelArrayKernel::reset_row_exact(int r, const RowIllumination& in, RowState& row) {
  // A row with the previous row's drive has its shape; anything else makes a new one.
  const bool same = intervals_ && shapes_used_ > 0 && shapes_[shapes_used_ - 1].signal_V == in.signal_V &&
                    shapes_[shapes_used_ - 1].background_V == in.background_V &&
                    shapes_[shapes_used_ - 1].centre_px == in.centre_px;
  row.shape = same ? shapes_used_ - 1 : make_shape(r, in, row);
  const RowShape& s = shapes_[static_cast<std::size_t>(row.shape)];
  row.first = s.first, row.last = s.last, row.threshold_V = s.threshold_V;
  pixels_simulated_ += std::max(0, s.last - s.first + 1);
  row.band_at = band_k_.size();
  row.uniforms = 0;
  if (!intervals_) {  // every window pixel was looked at and decided in make_shape
    for (const BandPixel& p : s.band) band_k_.push_back(static_cast<std::uint8_t>(p.certain));
    return;
  }
  pixels_examined_ += static_cast<long long>(s.band.size());
  for (const BandPixel& p : s.band) {
    int k = p.certain;
    if (k < 0 && s.by_uniform) {  // drawn in finish_row_exact, once every row's uniform is made
      draw_rc_.push_back(row_column(static_cast<std::uint32_t>(r), static_cast<std::uint32_t>(p.column)));
      ++row.uniforms;
      k = 0;
    } else if (k < 0) {
      k = draw(r, s, p, *shape_entry_);
    }
    band_k_.push_back(static_cast<std::uint8_t>(k));
  }
}

void PixelArrayKernel::finish_row_exact(int r, const double*& u) {
  // The row's uniforms (keyed_uniforms, in the order reset_row_exact asked for them) inverted, as
  // draw() would one by one; then its extents.
  const RowState& row = rows_[static_cast<std::size_t>(r)];
  RowShape& s = shapes_[static_cast<std::size_t>(row.shape)];
  std::uint8_t* fk = band_k_.data() + row.band_at;
  if (row.uniforms > 0) {
    if (row.shape != finish_shape_) {  // rows of one shape share its threshold entry
      finish_shape_ = row.shape;
      finish_entry_ = &exact_->entry(s.threshold_V);
    }
    ThresholdEntry& e = *finish_entry_;
    pixels_drawn_ += row.uniforms;
    for (std::size_t j = 0; j < s.band.size(); ++j) {
      const BandPixel& p = s.band[j];
      if (p.certain >= 0) continue;
      fk[j] = static_cast<std::uint8_t>(p.prepared ? exact_->invert_prepared(p.drive, e, s.cut.data() + p.cut_at, *u)
                                                   : exact_->invert_first_firing(p.drive, e, *u));
      ++u;
    }
  }
  fill_extents(r, s, fk);
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
  act.clear();
  if (k == 0) return;
  act.set_range(s.held_first[static_cast<std::size_t>(k - 1)], s.held_last[static_cast<std::size_t>(k - 1)]);
  for (std::size_t j = 0; j < s.band.size(); ++j) act.set(s.band[j].column, fired_by(fk[j], k));
}

void PixelArrayKernel::build_row(int r) const {
  const RowState& row = rows_[static_cast<std::size_t>(r)];
  set_row_bits(act_[static_cast<std::size_t>(r)], shapes_[static_cast<std::size_t>(row.shape)],
               band_k_.data() + row.band_at, sampling_);
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
// A row's N extents copied: the usual counts with a constant size (a call to memcpy for 16 bytes
// costs more than the rest of a memo hit).
inline void copy_extents(int* to, const int* from, int n) {
  if (n == 4) {
    std::memcpy(to, from, 4 * sizeof(int));
  } else if (n == 8) {
    std::memcpy(to, from, 8 * sizeof(int));
  } else {
    std::copy_n(from, n, to);
  }
}
}  // namespace

void PixelArrayKernel::fill_extents(int r, RowShape& s, const std::uint8_t* fk) {
  // Per sampling: the held core range widened by the band pixels fired by then (without branches on
  // the random first firings: no range is first = INT_MAX, last = -1 here). A band pixel inside the
  // held range that has not fired (its draw fell in a 2^-56 tail of a certain outcome) punches a
  // hole that may be at the range's edge: such a row takes its extents from its bits.
  // The extents are a function of the band's first firings, and the rows of a shape mostly repeat a
  // few patterns of them (two rows in three on the plane map repeat the previous row's): a small
  // memo per shape, keyed by the packed pattern, answers those.
  const int N = config_.multisampling.samplings;
  const std::size_t at = static_cast<std::size_t>(r) * static_cast<std::size_t>(N);
  int* first = extent_first_.data() + at;
  int* last = extent_last_.data() + at;
  const std::size_t n = s.band.size();
  std::uint64_t key = RowShape::kNoPattern;
  std::size_t slot = 0;
  if (n < 8) {
    key = static_cast<std::uint64_t>(n) << 56;
    for (std::size_t j = 0; j < n; ++j) key |= static_cast<std::uint64_t>(fk[j]) << (8 * j);
    slot = static_cast<std::size_t>((key * 0x9e3779b97f4a7c15ULL) >> 60) % RowShape::kMemo;
    if (s.memo_key[slot] == key) {
      const std::size_t m = slot * static_cast<std::size_t>(N);
      copy_extents(first, s.memo_first.data() + m, N);
      copy_extents(last, s.memo_last.data() + m, N);
      return;
    }
  }
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
  if (hole) extents_from_bits(r, s, fk);
  if (key == RowShape::kNoPattern) return;
  s.memo_key[slot] = key;
  const std::size_t m = slot * static_cast<std::size_t>(N);
  copy_extents(s.memo_first.data() + m, first, N);
  copy_extents(s.memo_last.data() + m, last, N);
}

void PixelArrayKernel::extents_from_bits(int r, const RowShape& s, const std::uint8_t* fk) {
  const int N = config_.multisampling.samplings;
  const std::size_t at = static_cast<std::size_t>(r) * static_cast<std::size_t>(N);
  ActivationRow bits(columns());
  for (int k = 1; k <= N; ++k) {
    set_row_bits(bits, s, fk, k);
    extent_first_[at + static_cast<std::size_t>(k - 1)] = bits.first();
    extent_last_[at + static_cast<std::size_t>(k - 1)] = bits.last();
  }
}

int PixelArrayKernel::make_shape(int r, const RowIllumination& in, RowState& row) {
  const int N = config_.multisampling.samplings;
  if (static_cast<int>(shapes_.size()) <= shapes_used_) shapes_.emplace_back();
  RowShape& s = shapes_[static_cast<std::size_t>(shapes_used_)];
  set_window(in, row);
  s.signal_V = in.signal_V, s.background_V = in.background_V, s.centre_px = in.centre_px;
  s.first = row.first, s.last = row.last, s.threshold_V = row.threshold_V;
  s.core_first.assign(static_cast<std::size_t>(N), 0);
  s.core_last.assign(static_cast<std::size_t>(N), -1);
  s.held_first.assign(static_cast<std::size_t>(N), std::numeric_limits<int>::max());
  s.held_last.assign(static_cast<std::size_t>(N), -1);
  s.band.clear();
  s.cut.clear();
  s.by_uniform = false;
  s.memo_key.fill(RowShape::kNoPattern);
  s.memo_first.resize(RowShape::kMemo * static_cast<std::size_t>(N));
  s.memo_last.resize(RowShape::kMemo * static_cast<std::size_t>(N));
  if (s.last >= s.first) {
    ThresholdEntry& e = exact_->entry(s.threshold_V);
    shape_entry_ = &e;
    if (!intervals_) {
      // Every window pixel one by one; the certain ones draw nothing. Only those that fire are kept.
      pixels_examined_ += s.last - s.first + 1;
      for (int i = s.first; i <= s.last; ++i) {
        BandPixel p = look_at(i, in, e);
        if (p.certain < 0) p.certain = draw(r, s, p, e);
        if (p.certain > 0) s.band.push_back(p);
      }
    } else {
      // Certain pixels by intervals; the band pixels (r_1 < d < s_N on either side) one by one.
      const RowCertainty& c = intervals_->of(in.signal_V, in.background_V, e.b);
      const double x0 = in.centre_px;
      core_ranges(c, x0, s);
      const double inner = std::max(c.fired_within.front(), 0.0), outer = c.never_beyond.back();
      auto col = [&](double x) {
        return static_cast<int>(std::clamp(x, static_cast<double>(s.first), static_cast<double>(s.last)));
      };
      const int left_lo = outer == RowCertainty::kAll ? s.first : col(std::floor(x0 - outer));
      const int left_hi = col(std::ceil(x0 - inner));
      const int right_lo = std::max(col(std::floor(x0 + inner)), left_hi + 1);
      const int right_hi = outer == RowCertainty::kAll ? s.last : col(std::ceil(x0 + outer));
      s.by_uniform = inversion_ && ExactActivation::inversion_applies(e);
      for (int i = left_lo; i <= right_hi; i = (i == left_hi && right_lo > i + 1) ? right_lo : i + 1) {
        if (c.classify(std::fabs(i - x0)) >= 0) continue;
        BandPixel p = look_at(i, in, e);
        if (p.certain < 0 && inversion_ && ExactActivation::inversion_applies(e)) {
          // Every row with this drive draws it against the same f~ values: look them up once.
          p.prepared = true;
          p.cut_at = s.cut.size();
          s.cut.resize(s.cut.size() + 2 * static_cast<std::size_t>(N));
          exact_->prepare_inversion(p.drive, e, s.cut.data() + p.cut_at);
        }
        s.band.push_back(p);
      }
    }
  }
  hold_ranges(s);
  return shapes_used_++;
}

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

void PixelArrayKernel::core_ranges(const RowCertainty& c, double x0, RowShape& s) const {
  // Columns with |i - x0| <= r_k, found exactly as classify() sees them (the same d = |i - x0|).
  for (std::size_t k = 0; k < c.fired_within.size(); ++k) {
    const double rk = c.fired_within[k];
    if (rk < 0) continue;
    int a = s.first, b = s.last;
    if (rk != RowCertainty::kAll) {
      a = static_cast<int>(std::clamp(std::ceil(x0 - rk), s.first - 1.0, s.last + 1.0));
      b = static_cast<int>(std::clamp(std::floor(x0 + rk), s.first - 1.0, s.last + 1.0));
      while (a <= b && std::fabs(a - x0) > rk) ++a;
      while (a - 1 >= s.first && std::fabs(a - 1 - x0) <= rk) --a;
      while (b >= a && std::fabs(b - x0) > rk) --b;
      while (b + 1 <= s.last && std::fabs(b + 1 - x0) <= rk) ++b;
      a = std::max(a, s.first);
      b = std::min(b, s.last);
    }
    s.core_first[k] = a;
    s.core_last[k] = b;
  }
}

PixelArrayKernel::BandPixel PixelArrayKernel::look_at(int i, const RowIllumination& in, ThresholdEntry& e) const {
  const int N = config_.multisampling.samplings;
  BandPixel p;
  p.column = i;
  p.drive = {in.signal_V, golden::spot_profile(config_.spot, i - in.centre_px), in.background_V, dark_V_, 0.0};
  // The per-sampling path's mean per interval, expression for expression.
  p.drive.mean_step_e =
      golden::pixel_swing_V(in.signal_V, p.drive.profile, in.background_V, dark_V_, 1.0) * electrons_per_V_ / N;
  p.certain = exact_->certain_first_firing(p.drive, e.b);
  return p;
}

int PixelArrayKernel::draw(int r, const RowShape& s, const BandPixel& p, ThresholdEntry& e) {
  ++pixels_drawn_;
  const std::uint64_t key =
      pixel_key_in_frame(frame_key_, static_cast<std::uint32_t>(r), static_cast<std::uint32_t>(p.column));
  if (p.prepared) return exact_->invert_prepared(p.drive, e, s.cut.data() + p.cut_at, keyed_uniform(key));
  if (inversion_ && ExactActivation::inversion_applies(e))
    return exact_->invert_first_firing(p.drive, e, keyed_uniform(key));
  pcg32 rng = pixel_stream(key);
  return exact_->draw_first_firing(p.drive, e.threshold_V, rng);
}

void PixelArrayKernel::sample_exact(int) {
  // The firing samplings were decided at the reset: the rows' extents are ready, their bits are made
  // when asked for (row()).
  ++generation_;
}

}  // namespace rangesim::systemc
