#include "systemc/common/keyed_uniforms.h"

#include <cstring>

// GCC's function clones and target attributes are an x86 ELF feature; other targets get the loop.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__) && defined(__ELF__)
#define RANGESIM_KEYED_UNIFORMS_X86 1
#include <immintrin.h>
#endif

#include "systemc/common/random_stream.h"

namespace rangesim::systemc {

namespace {

#ifdef RANGESIM_KEYED_UNIFORMS_X86
__attribute__((target_clones("arch=x86-64-v4", "default")))
#endif
void plain_loop(std::uint64_t frame_key, const std::uint64_t* rc, double* u, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) u[i] = keyed_uniform(splitmix64(frame_key ^ rc[i]));
}

#ifdef RANGESIM_KEYED_UNIFORMS_X86
__attribute__((target_clones("arch=x86-64-v4", "default")))
#endif
void plain_grid(std::uint64_t frame_key, std::uint32_t row0, std::size_t rows, const std::uint32_t* columns,
                std::size_t m, double* u) {
  for (std::size_t t = 0; t < m; ++t, u += rows)
    for (std::size_t i = 0; i < rows; ++i)
      u[i] = keyed_uniform(splitmix64(frame_key ^ row_column(row0 + static_cast<std::uint32_t>(i), columns[t])));
}

#ifdef RANGESIM_KEYED_UNIFORMS_X86
// AVX2 without AVX-512: four 64-bit lanes, the multiplies made of 32-bit ones (times), and the
// 53-bit integer converted to double exactly in two halves (AVX2 has no 64-bit integer to double
// conversion): hi 2^32 + lo with each half put into a double's mantissa under a fixed exponent
// (2^84 and 2^52) and those taken off again; every step is exact, so the bits are the plain loop's.
typedef std::uint64_t U64x4 __attribute__((vector_size(32)));
typedef double F64x4 __attribute__((vector_size(32)));

// x C mod 2^64 in each lane: xl Cl + ((xl Ch + xh Cl) mod 2^32) 2^32, the cross terms' low halves
// from one 32-bit multiply of x by C with its halves swapped. The compiler's own lowering takes
// three 32 x 32 -> 64-bit multiplies, the loop's limit: with this the uniforms took 1.61-1.65 ns
// against 1.99 (isolated grid loop, pinned, with the two keys in registers beside the lanes).
template <std::uint64_t C>
__attribute__((target("avx2"), always_inline)) inline U64x4 times(U64x4 x) {
  const __m256i v = reinterpret_cast<__m256i>(x);
  const __m256i cross = _mm256_mullo_epi32(v, _mm256_set1_epi64x(static_cast<long long>((C >> 32) | (C << 32))));
  const __m256i high = _mm256_and_si256(_mm256_add_epi64(cross, _mm256_slli_epi64(cross, 32)),
                                        _mm256_set1_epi64x(static_cast<long long>(0xffffffff00000000ULL)));
  return reinterpret_cast<U64x4>(
      _mm256_add_epi64(_mm256_mul_epu32(v, _mm256_set1_epi64x(static_cast<long long>(C))), high));
}

__attribute__((target("avx2"), always_inline)) inline U64x4 splitmix64x4(U64x4 x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = times<0xbf58476d1ce4e5b9ULL>(x ^ (x >> 30));
  x = times<0x94d049bb133111ebULL>(x ^ (x >> 27));
  return x ^ (x >> 31);
}

// Four keys' uniforms (row_column in each lane) into u[0..3].
__attribute__((target("avx2"), always_inline)) inline void four_uniforms(std::uint64_t frame_key, U64x4 rc, double* u) {
  constexpr double kTwo84Plus52 = 19342813118337666422669312.0;  // 2^84 + 2^52

  // keyed_uniform's 53 bits, then as a double in (0, 1)
  const U64x4 x = splitmix64x4(splitmix64x4(rc ^ frame_key) ^ 0x6b65796564753031ULL) >> 11;
  const U64x4 hi = (x >> 32) | 0x4530000000000000ULL, lo = (x & 0xffffffffULL) | 0x4330000000000000ULL;
  F64x4 h, l;
  std::memcpy(&h, &hi, sizeof h);
  std::memcpy(&l, &lo, sizeof l);
  const F64x4 v = ((h - kTwo84Plus52) + l + 0.5) * (1.0 / 9007199254740992.0);
  std::memcpy(u, &v, sizeof v);
}

// The plain loop's formula for one key, inlined among the vector steps: the general-purpose
// registers' 64-bit multiplies run beside the vector unit's. Four uniforms in the lanes and two
// here per step took 2.00-2.03 ns a uniform against 2.32-2.34 with the lanes alone (isolated grid
// loop, pinned, before times).
__attribute__((target("avx2"), always_inline)) inline double one_uniform(std::uint64_t frame_key, std::uint64_t rc) {
  return keyed_uniform(splitmix64(frame_key ^ rc));
}

__attribute__((target("avx2"))) void avx2_loop(std::uint64_t frame_key, const std::uint64_t* rc, double* u,
                                               std::size_t n) {
  std::size_t i = 0;
  for (; i + 6 <= n; i += 6) {
    U64x4 x;
    std::memcpy(&x, rc + i, sizeof x);
    four_uniforms(frame_key, x, u + i);
    u[i + 4] = one_uniform(frame_key, rc[i + 4]);
    u[i + 5] = one_uniform(frame_key, rc[i + 5]);
  }
  for (; i < n; ++i) u[i] = one_uniform(frame_key, rc[i]);
}

// The grid's keys made in the lanes (four consecutive rows of one column) instead of read.
__attribute__((target("avx2"))) void avx2_grid(std::uint64_t frame_key, std::uint32_t row0, std::size_t rows,
                                               const std::uint32_t* columns, std::size_t m, double* u) {
  constexpr std::uint64_t kRow = std::uint64_t{1} << 32;
  for (std::size_t t = 0; t < m; ++t, u += rows) {
    const std::uint64_t first = row_column(row0, columns[t]);
    U64x4 rc = {first, first + kRow, first + 2 * kRow, first + 3 * kRow};
    std::size_t i = 0;
    for (; i + 6 <= rows; i += 6, rc += 6 * kRow) {
      four_uniforms(frame_key, rc, u + i);
      u[i + 4] = one_uniform(frame_key, first + (i + 4) * kRow);
      u[i + 5] = one_uniform(frame_key, first + (i + 5) * kRow);
    }
    for (; i < rows; ++i) u[i] = one_uniform(frame_key, first + i * kRow);  // (row0 + i wraps as in row_column)
  }
}
#endif

}  // namespace

void keyed_uniforms(std::uint64_t frame_key, const std::uint64_t* rc, double* u, std::size_t n) {
#ifdef RANGESIM_KEYED_UNIFORMS_X86
  static const bool avx2 = __builtin_cpu_supports("avx2") && !__builtin_cpu_supports("avx512dq");
  if (avx2) return avx2_loop(frame_key, rc, u, n);
#endif
  plain_loop(frame_key, rc, u, n);
}

void keyed_uniforms_grid(std::uint64_t frame_key, std::uint32_t row0, std::size_t rows, const std::uint32_t* columns,
                         std::size_t m, double* u) {
#ifdef RANGESIM_KEYED_UNIFORMS_X86
  static const bool avx2 = __builtin_cpu_supports("avx2") && !__builtin_cpu_supports("avx512dq");
  if (avx2) return avx2_grid(frame_key, row0, rows, columns, m, u);
#endif
  plain_grid(frame_key, row0, rows, columns, m, u);
}

}  // namespace rangesim::systemc
