// The pixel array's exact path (pixel_array_kernel.h, activation_sampler.h): each window pixel's
// first firing sampling decided at the reset, certain ones without a draw; with certain intervals
// (certain_intervals.h) only the band between them is looked at one by one. What the latch then
// holds (extents and bits): pixel_array_extents.cpp.
#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstring>
#include <limits>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif
// GCC's target attribute is an x86 ELF feature; elsewhere the SSE2 or plain loop alone.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && defined(__ELF__)
#define RANGESIM_EXACT_AVX2 1
#include <immintrin.h>
#endif

#include "golden/common/pixel.h"
#include "golden/common/spot.h"
#include "systemc/common/keyed_uniforms.h"
#include "systemc/common/random_stream.h"
#include "systemc/ls_conventional/pixel_array_kernel.h"

namespace rangesim::systemc {

namespace {
// Grows v to hold n, never shrinks it: on a scene where every row has its own drive the buffers
// below are sized once a run, and a resize down then up again cleared and grew them every time.
template <class V>
void at_least(V& v, std::size_t n) {
  if (v.size() < n) v.resize(std::max(n, 2 * v.size()));
}

#ifdef RANGESIM_EXACT_AVX2
// invert_run's loop for a pixel with one random sampling, four rows a step where the CPU has AVX2
// (the SSE2 loop takes two): row i's first firing kf where ut[i] < lo, else ke, at bit `shift` of
// ot[i] (Keyed: ORed into it). Returns the rows done (a multiple of 4); `between` is nonzero when
// some ut[i] fell between lo and hi.
template <bool Keyed>
__attribute__((target("avx2"))) std::size_t single_draws_avx2(const double* __restrict ut, std::size_t R, double lo,
                                                              double hi, std::uint64_t kf, std::uint64_t ke,
                                                              unsigned shift, std::uint64_t* __restrict ot,
                                                              std::uint64_t& between) {
  const __m256d v_lo = _mm256_set1_pd(lo), v_hi = _mm256_set1_pd(hi);
  const __m256i v_ke = _mm256_set1_epi64x(static_cast<long long>(ke << shift));
  const __m256i v_diff = _mm256_set1_epi64x(static_cast<long long>((kf ^ ke) << shift));
  __m256i v_between = _mm256_setzero_si256();
  std::size_t i = 0;
  for (; i + 4 <= R; i += 4) {
    const __m256d x = _mm256_loadu_pd(ut + i);
    const __m256i fire = _mm256_castpd_si256(_mm256_cmp_pd(x, v_lo, _CMP_LT_OQ));
    __m256i k = _mm256_xor_si256(v_ke, _mm256_and_si256(v_diff, fire));
    if (Keyed) k = _mm256_or_si256(k, _mm256_loadu_si256(reinterpret_cast<const __m256i*>(ot + i)));
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(ot + i), k);
    v_between =
        _mm256_or_si256(v_between, _mm256_andnot_si256(fire, _mm256_castpd_si256(_mm256_cmp_pd(x, v_hi, _CMP_LT_OQ))));
  }
  between |= static_cast<std::uint64_t>(_mm256_movemask_pd(_mm256_castsi256_pd(v_between)));
  return i;
}

bool avx2() {  // asked once, after the CPU's features are known (not during static initialisation)
  static const bool yes = __builtin_cpu_supports("avx2");
  return yes;
}

// How many bytes from the start a and b agree on (at most n), 32 a step.
__attribute__((target("avx2"))) std::size_t equal_prefix_avx2(const unsigned char* a, const unsigned char* b,
                                                              std::size_t n) {
  std::size_t i = 0;
  for (; i + 32 <= n; i += 32) {
    const __m256i x = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(a + i));
    const __m256i y = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(b + i));
    const unsigned same = static_cast<unsigned>(_mm256_movemask_epi8(_mm256_cmpeq_epi8(x, y)));
    if (same != 0xffffffffU) return i + static_cast<std::size_t>(__builtin_ctz(~same));
  }
  while (i < n && a[i] == b[i]) ++i;
  return i;
}
#endif

// How many of the n rows after p[0] repeat it byte for byte (p[1] == p[0], p[2] == p[1], ...): a
// run's rows on a plane are one drive, and comparing their bytes is a vector loop.
std::size_t repeated_rows(const RowIllumination* p, std::size_t n) {
  static_assert(sizeof(RowIllumination) == 3 * sizeof(double), "no padding bytes to compare");
  const auto* a = reinterpret_cast<const unsigned char*>(p + 1);
  const auto* b = reinterpret_cast<const unsigned char*>(p);
  const std::size_t bytes = n * sizeof(RowIllumination);
#ifdef RANGESIM_EXACT_AVX2
  if (avx2()) return equal_prefix_avx2(a, b, bytes) / sizeof(RowIllumination);
#endif
  std::size_t i = 0;
  while (i < bytes && a[i] == b[i]) ++i;
  return i / sizeof(RowIllumination);
}

bool same_drive(const RowIllumination& x, const RowIllumination& in) {
  return x.signal_V == in.signal_V && x.background_V == in.background_V && x.centre_px == in.centre_px;
}
}  // namespace

void PixelArrayKernel::reset_exact() {
  // Two passes around the short runs' uniforms (made in one vectorised batch by their keys): per
  // run of rows with one drive (every row of a plane), its shape, the rows' certain first firings
  // and, for a short run, the keys of the uniforms its random ones need; then per run the rows'
  // draws and extents, a long run's uniforms made there (draw_run).
  const int N = config_.multisampling.samplings;
  shapes_used_ = 0;
  // Every row adds at most one extent pattern (those of rows found in a shape's memo are shared).
  row_pattern_.resize(static_cast<std::size_t>(rows()));
  at_least(pattern_first_, static_cast<std::size_t>(rows()) * static_cast<std::size_t>(N));
  at_least(pattern_last_, static_cast<std::size_t>(rows()) * static_cast<std::size_t>(N));
  at_least(pattern_key_, static_cast<std::size_t>(rows()));
  patterns_ = 0;
  std::size_t band_total = 0, draws = 0;
  runs_.clear();
  for (int r0 = 0, r1 = 0; r0 < rows(); r0 = r1) {
    // The run: the rows with r0's drive. Without certain intervals every row makes its own shape
    // from every window pixel, and decides them there.
    const RowIllumination& in = stimulus_.rows[static_cast<std::size_t>(first_row_ + r0)];
    r1 = r0 + 1;
    // (A row equal to r0's in value but not in bytes, as -0 and +0, goes on the run as before.)
    if (intervals_)
      while (r1 < rows() && same_drive((&in)[r1 - r0], in))
        r1 += 1 + static_cast<int>(repeated_rows(&in + (r1 - r0), static_cast<std::size_t>(rows() - r1 - 1)));
    const int shape = make_shape(first_row_ + r0, in, rows_[static_cast<std::size_t>(r0)]);
    const RowShape& s = shapes_[static_cast<std::size_t>(shape)];
    const std::size_t count = static_cast<std::size_t>(r1 - r0), n = s.band.size();
    const int m = intervals_ && !s.one_by_one ? static_cast<int>(s.drawn_column.size()) : 0;
    pixels_simulated_ += static_cast<long long>(count) * std::max(0, s.last - s.first + 1);
    if (intervals_) pixels_examined_ += static_cast<long long>(count * n);
    // What its rows share is kept once, for the run (nothing is written per row).
    const std::size_t uniforms = count * static_cast<std::size_t>(m);
    const bool grid = m > 0 && count >= kGridRows;
    runs_.push_back(ExactRun{r0, r1, shape, m, band_total, grid ? 0 : draws, grid});
    at_least(band_k_, band_total + count * n + 8);  // 8 to spare (start_run)
    if (!grid) at_least(draw_rc_, draws + uniforms);
    start_run(runs_.back(), grid ? nullptr : draw_rc_.data() + draws);
    band_total += count * n;
    if (!grid) draws += uniforms;
  }
  uniforms_.resize(draws);
  keyed_uniforms(frame_key_, draw_rc_.data(), uniforms_.data(), draws);
  for (const ExactRun& run : runs_) {
    switch (N) {  // the usual counts unrolled (the preset's is 4)
      case 2: finish_run<2>(run); break;
      case 4: finish_run<4>(run); break;
      case 8: finish_run<8>(run); break;
      default: finish_run<0>(run);
    }
  }
}

const PixelArrayKernel::ExactRun& PixelArrayKernel::run_of(int r) const {
  const auto after =
      std::upper_bound(runs_.begin(), runs_.end(), r, [](int row, const ExactRun& run) { return row < run.r0; });
  assert(after != runs_.begin() && r < (after - 1)->r1);
  return *(after - 1);
}

void PixelArrayKernel::start_run(const ExactRun& run, std::uint64_t* rc) {
  // The run's rows (within the band), of one shape: their certain first firings, and the keys of the
  // uniforms finish_run inverts, drawn pixel by drawn pixel and row by row within (a grid's are
  // made with its uniforms: rc null), or, without inversion, the Gamma draws pixel by pixel.
  const int r0 = run.r0;
  const RowShape& s = shapes_[static_cast<std::size_t>(run.shape)];
  const std::size_t n = s.band.size(), R = static_cast<std::size_t>(run.r1 - r0);
  std::uint8_t* fk = band_k_.data() + run.band_at;
  // Rows are written in order, and base_k and band_k_ have 8 bytes to spare: a band of up to 8
  // pixels is one 8-byte move (a copy of a run-time size is a library call per row). The rows of a
  // shape with a memo key keep their first firings in their keys instead (finish_run).
  if (!keyed_rows(s)) {
    if (n <= 8) {
      for (std::size_t i = 0; i < R; ++i) std::memcpy(fk + i * n, s.base_k.data(), 8);
    } else {
      for (std::size_t i = 0; i < R; ++i) std::memcpy(fk + i * n, s.base_k.data(), n);
    }
  }
  if (run.uniforms > 0) {
    if (!rc) return;
    const std::uint64_t row0 = static_cast<std::uint64_t>(first_row_ + r0);
    for (std::size_t t = 0; t < s.drawn_column.size(); ++t, rc += R)
      for (std::size_t i = 0; i < R; ++i) rc[i] = ((row0 + i) << 32) | s.drawn_column[t];  // row_column()
  } else if (intervals_ && s.one_by_one) {
    ThresholdEntry& e = exact_->entry(s.threshold_V);
    for (std::size_t i = 0; i < R; ++i, fk += n)
      for (std::size_t j = 0; j < n; ++j)
        if (s.band[j].certain < 0)
          fk[j] = static_cast<std::uint8_t>(draw(first_row_ + r0 + static_cast<int>(i), s, s.band[j], e));
  }
}

namespace {
// invert_prepared's comparisons without a branch on u, which is random (their mispredictions were
// most of the draws' time): the first sampling whose upper cut exceeds u decides; there u below the
// lower cut fires (returns k, 1-based), else u sits between the cuts and golden's f must decide
// (sets `between`; ~2e-5 of the draws). No sampling decides: never fired (0). N = 0: n samplings at
// run time (n <= 30 with SSE2, else 62).
template <int N>
inline int first_firing_by_cuts(const double* cut, double u, int n, bool& between) {
  const int samplings = N > 0 ? N : n;
#if defined(__SSE2__)
  // One compare per sampling against its (lower, upper) pair: bit 2k is u < lower_k (fires), bit
  // 2k + 1 is u < upper_k (decides).
  const __m128d uu = _mm_set1_pd(u);
  std::uint64_t bits = 0;
  for (int k = 0; k < samplings; ++k)
    bits |= static_cast<std::uint64_t>(_mm_movemask_pd(_mm_cmplt_pd(uu, _mm_loadu_pd(cut + 2 * k)))) << (2 * k);
  const int j = __builtin_ctzll((bits & 0xaaaaaaaaaaaaaaaaULL) | (std::uint64_t{1} << (2 * samplings + 1)));
  const std::uint64_t fires = (bits >> (j - 1)) & 1U;  // bit 2k of the deciding k = j / 2 (0 past the end)
  between = ((bits >> j) & ~fires) & 1U;
  return ((j >> 1) + 1) & -static_cast<int>(fires);
#else
  std::uint64_t open = 0, fire = 0;
  for (int k = 0; k < samplings; ++k) {
    open |= static_cast<std::uint64_t>(u < cut[2 * k + 1]) << k;
    fire |= static_cast<std::uint64_t>(u < cut[2 * k]) << k;
  }
  const int k = __builtin_ctzll(open | (std::uint64_t{1} << samplings));  // bit `samplings` of both is 0
  between = ((open & ~fire) >> k) & 1U;
  return (k + 1) & -static_cast<int>((fire >> k) & 1U);
#endif
}
}  // namespace

template <int N, bool Keyed>
void PixelArrayKernel::draw_run(const ExactRun& run, const RowShape& s, std::size_t R, std::uint64_t* out) {
  // A short run's uniforms are in the frame's batch. A long run's are made as a grid (keys made in
  // the vector lanes), a drawn pixel's column just before its compares: one column's uniforms stay
  // in the L1 cache, where the whole grid's (8.6 KB a frame access on the plane) did not.
  const std::size_t m = static_cast<std::size_t>(run.uniforms);
  if (!run.grid) {
    invert_run<N, Keyed>(s, R, uniforms_.data() + run.u_at, out, 0, m);
    return;
  }
  at_least(column_u_, R);
  for (std::size_t t = 0; t < m; ++t) {
    keyed_uniforms_grid(frame_key_, static_cast<std::uint32_t>(first_row_ + run.r0), R, s.drawn_column.data() + t, 1,
                        column_u_.data());
    invert_run<N, Keyed>(s, R, column_u_.data(), out, t, t + 1);
  }
}

template <int N, bool Keyed>
void PixelArrayKernel::invert_run(const RowShape& s, std::size_t R, const double* u, std::uint64_t* out, std::size_t t0,
                                  std::size_t t1) {
  // The first firing of drawn pixel t (t0 <= t < t1) on the run's row i, from u[(t - t0) R + i]:
  // into out[t R + i], or (Keyed) into row i's memo key out[i] at the pixel's byte, 8 at[t] (the
  // key holds the shape's certain first firings already, and 0 there). A pixel with one random sampling is a compare a
  // row, over the rows in one vector loop (the first firing selected by the compare's mask: a
  // branch on u mispredicts every other draw); u between its cuts (~2e-5 of the draws) is decided
  // afterwards by golden's f. A pixel with several is one vector compare a sampling
  // (first_firing_by_cuts).
  const int n = config_.multisampling.samplings;
  const std::size_t stride = 2 * static_cast<std::size_t>(n);
  for (std::size_t t = t0; t < t1; ++t) {
    const double* __restrict ut = u + (t - t0) * R;
    std::uint64_t* __restrict ot = Keyed ? out : out + t * R;
    const unsigned shift = Keyed ? 8U * static_cast<unsigned>(s.drawn_at[t]) : 0U;
    const auto put = [ot, shift](std::size_t i, std::uint64_t k) {
      if (Keyed)
        ot[i] = (ot[i] & ~(std::uint64_t{0xff} << shift)) | (k << shift);
      else
        ot[i] = k;
    };
    const double* cut = s.cut.data() + t * stride;
    const PixelDrive& drive = s.band[static_cast<std::size_t>(s.drawn_at[t])].drive;
    if (s.drawn_single[t]) {
      const double lo = s.drawn_lo[t], hi = s.drawn_hi[t];
      const std::uint64_t kf = s.drawn_fire[t], ke = s.drawn_else[t];
      std::uint64_t between = 0;
      std::size_t i = 0;
#ifdef RANGESIM_EXACT_AVX2
      if (avx2()) i = single_draws_avx2<Keyed>(ut, R, lo, hi, kf, ke, shift, ot, between);
#endif
#if defined(__SSE2__)
      // Two rows a step (the compiler does not vectorise the loop below by itself).
      const __m128d v_lo = _mm_set1_pd(lo), v_hi = _mm_set1_pd(hi);
      const __m128i v_ke = _mm_set1_epi64x(static_cast<long long>(ke << shift));
      const __m128i v_diff = _mm_set1_epi64x(static_cast<long long>((kf ^ ke) << shift));
      __m128i v_between = _mm_setzero_si128();
      for (; i + 2 <= R; i += 2) {
        const __m128d x = _mm_loadu_pd(ut + i);
        const __m128i fire = _mm_castpd_si128(_mm_cmplt_pd(x, v_lo));
        __m128i k = _mm_xor_si128(v_ke, _mm_and_si128(v_diff, fire));
        if (Keyed) k = _mm_or_si128(k, _mm_loadu_si128(reinterpret_cast<const __m128i*>(ot + i)));
        _mm_storeu_si128(reinterpret_cast<__m128i*>(ot + i), k);
        v_between = _mm_or_si128(v_between, _mm_andnot_si128(fire, _mm_castpd_si128(_mm_cmplt_pd(x, v_hi))));
      }
      between |= static_cast<std::uint64_t>(_mm_movemask_pd(_mm_castsi128_pd(v_between)));
#endif
      for (; i < R; ++i) {
        const std::uint64_t fire = -static_cast<std::uint64_t>(ut[i] < lo);
        put(i, ke ^ ((kf ^ ke) & fire));
        between |= ~fire & -static_cast<std::uint64_t>(ut[i] < hi);
      }
      if (__builtin_expect(between != 0, 0))
        for (std::size_t i = 0; i < R; ++i)
          if (ut[i] >= lo && ut[i] < hi)
            put(i, static_cast<std::uint64_t>(exact_->invert_prepared(drive, *finish_entry_, cut, ut[i])));
      continue;
    }
    for (std::size_t i = 0; i < R; ++i) {
      bool between = true;
      int k = N == 0 && n > 30 ? 0 : first_firing_by_cuts<N>(cut, ut[i], n, between);
      if (__builtin_expect(between, 0))  // (and every draw with more samplings than a mask holds)
        k = exact_->invert_prepared(drive, *finish_entry_, cut, ut[i]);
      put(i, static_cast<std::uint64_t>(k));
    }
  }
}

template <int N>
void PixelArrayKernel::finish_run(const ExactRun& run) {
  // The run's rows, of one shape: their uniforms (drawn pixel by drawn pixel and row by row
  // within: draw_run) inverted as draw() would one by one, then row by row its first firings, the
  // memo key of them and its extents.
  const int r0 = run.r0;
  RowShape& s = shapes_[static_cast<std::size_t>(run.shape)];
  const std::size_t n = s.band.size(), R = static_cast<std::size_t>(run.r1 - r0);
  std::uint8_t* fk = band_k_.data() + run.band_at;
  const std::size_t m = static_cast<std::size_t>(run.uniforms);
  if (m > 0) {
    finish_entry_ = &exact_->entry(s.threshold_V);  // for the rare draws between the cuts
    pixels_drawn_ += static_cast<long long>(m * R);
  }
  if (keyed_rows(s)) {
    // The rows' keys (their first firings packed, n << 56 | fk[j] << 8 j): the shape's, with the
    // draws put in by the inversion's vector loops over the rows, a drawn pixel at a time. A key's
    // low n bytes are the row's first firings; they are not stored per row: a row's pattern keeps
    // the key it was made from (pattern_key_), which is the key of every row that shares it.
    at_least(keys_, R);
    std::uint64_t* __restrict keys = keys_.data();
    for (std::size_t i = 0; i < R; ++i) keys[i] = s.base_key;
    if (m > 0) draw_run<N, true>(run, s, R, keys);
    std::uint32_t* const pattern_of_row = row_pattern_.data() + r0;  // (sized at the reset)
    for (std::size_t i = 0; i < R; ++i) {
      const std::uint64_t key = keys[i];
      const std::size_t slot = RowShape::memo_slot(key);
      if (s.memo_key[slot] == key) {  // the shape's memo (fill_extents): the row shares its pattern
        pattern_of_row[i] = s.memo_pattern[slot];
      } else {  // not in the memo: worked out, and kept there
        std::uint8_t first_firings[8];
        std::memcpy(first_firings, &key, 8);
        fill_extents(r0 + static_cast<int>(i), s, first_firings, key);
      }
    }
    return;
  }
  if (m > 0) {
    at_least(k_scratch_, m * R);
    draw_run<N, false>(run, s, R, k_scratch_.data());
  }
  const std::uint64_t* K = k_scratch_.data();
  const int* at = s.drawn_at.data();
  for (std::size_t i = 0; i < R; ++i, fk += n) {
    const int r = r0 + static_cast<int>(i);
    std::uint64_t key = s.base_key;
    for (std::size_t t = 0; t < m; ++t) {
      const std::uint64_t k = K[t * R + i];
      fk[at[t]] = static_cast<std::uint8_t>(k);
      key |= k << (8 * (at[t] & 7));  // (a band of 8 or more has no key: kNoPattern stays)
    }
    if (m == 0 && s.one_by_one && key != RowShape::kNoPattern)  // drawn in start_run
      for (std::size_t j = 0; j < n; ++j) key |= static_cast<std::uint64_t>(fk[j]) << (8 * j);
    if (key != RowShape::kNoPattern) {  // the shape's memo (fill_extents): the row shares its pattern
      const std::size_t slot = RowShape::memo_slot(key);
      if (s.memo_key[slot] == key) {
        row_pattern_[static_cast<std::size_t>(r)] = s.memo_pattern[slot];
        continue;
      }
    }
    fill_extents(r, s, fk, key);  // not in the memo: worked out, and kept there
  }
}

void PixelArrayKernel::plan_draws(RowShape& s) const {
  // What every row of the shape repeats (start_run, finish_run). Sized, then every entry written:
  // on a scene where every row has its own drive this runs once a row.
  const std::size_t n = s.band.size();
  const int N = config_.multisampling.samplings;
  s.base_k.resize(n + 8);  // 8 to spare (start_run)
  std::memset(s.base_k.data() + n, 0, 8);
  s.drawn_at.clear();
  s.drawn_column.clear();
  s.one_by_one = false;
  for (std::size_t j = 0; j < n; ++j) {
    const BandPixel& p = s.band[j];
    s.base_k[j] = static_cast<std::uint8_t>(std::max(p.certain, 0));
    if (p.certain >= 0) continue;
    if (!s.by_uniform) {
      s.one_by_one = true;
    } else {
      assert(p.prepared && p.cut_at == s.drawn_at.size() * 2 * static_cast<std::size_t>(N));
      s.drawn_at.push_back(static_cast<int>(j));
      s.drawn_column.push_back(static_cast<std::uint32_t>(p.column));
    }
  }
  // The drawn pixels with one random sampling (cuts other than f = 0: 0, 0 and f = 1: 2, 2).
  const std::size_t m = s.drawn_at.size();
  s.drawn_lo.resize(m), s.drawn_hi.resize(m);
  s.drawn_single.resize(m), s.drawn_fire.resize(m), s.drawn_else.resize(m);
  for (std::size_t t = 0; t < m; ++t) {
    const double* cut = s.cut.data() + t * 2 * static_cast<std::size_t>(N);
    int k = 0;
    while (k < N && cut[2 * k] == 0 && cut[2 * k + 1] == 0) ++k;  // f = 0
    const bool single = k < N && (k + 1 == N || (cut[2 * k + 2] == 2 && cut[2 * k + 3] == 2));  // f = 1 after
    s.drawn_single[t] = single;
    s.drawn_lo[t] = single ? cut[2 * k] : 0.0, s.drawn_hi[t] = single ? cut[2 * k + 1] : 0.0;
    s.drawn_fire[t] = static_cast<std::uint8_t>(single ? k + 1 : 0);
    s.drawn_else[t] = static_cast<std::uint8_t>(single && k + 1 < N ? k + 2 : 0);
  }
  s.base_key = RowShape::kNoPattern;
  if (n < 8) {
    s.base_key = static_cast<std::uint64_t>(n) << 56;
    for (std::size_t j = 0; j < n; ++j) s.base_key |= static_cast<std::uint64_t>(s.base_k[j]) << (8 * j);
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
  if (s.last >= s.first) {
    ThresholdEntry& e = exact_->entry(s.threshold_V);
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
  plan_draws(s);
  return shapes_used_++;
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
