#pragma once
// Counter-based random streams for the clock-level models (keyed by seed, operating point and trial, so a result does
// not depend on thread count or order).
//
// Every random draw of a pixel in a frame access comes from its own generator, seeded from a hash
// of the key (seed, frame, row, column). The key, not the order in which pixels or rows are
// visited, decides the bits: a result does not depend on event skipping, sparse windows, thread
// count or the harness (bare kernel or SystemC). std::seed_seq is not counter-based (it mixes a
// sequence of words into a state, with no structure); here the key is folded in with the
// SplitMix64 finaliser, one 64-bit word at a time, and the result seeds a pcg32 (state and stream).
//
// Draws of one pixel in one frame access, in this order (docs/simulate.md):
//   1.-2. kTC reset noise and read noise (one normal pair), at the pixel reset;
//   3. per sampling k = 1..N, the Poisson count of photo-/dark electrons integrated in (t_{k-1}, t_k].
// A switched-off kTC or read noise still consumes its draw, so switching one source does not move
// the bits of the others (the Poisson counts come last).
#include <cmath>
#include <cstdint>
#include <random>

#include <pcg_random.hpp>

namespace rangesim::systemc {

// SplitMix64 finaliser (Steele, Lea, Flood 2014): a bijective 64-bit mix.
inline std::uint64_t splitmix64(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

// Hash of the key (seed, frame, row, column): each word is mixed in after the previous ones. The
// first two words' part (frame_stream_key) can be made once per frame access (pixel_key_in_frame).
inline std::uint64_t frame_stream_key(std::uint64_t seed, std::uint64_t frame) {
  return splitmix64(splitmix64(seed ^ 0x72616e676573696dULL) ^ frame);  // "rangesim"
}
inline std::uint64_t pixel_key_in_frame(std::uint64_t frame_key, std::uint32_t row, std::uint32_t column) {
  return splitmix64(frame_key ^ ((static_cast<std::uint64_t>(row) << 32) | column));
}
inline std::uint64_t pixel_stream_key(std::uint64_t seed, std::uint64_t frame, std::uint32_t row,
                                      std::uint32_t column) {
  return pixel_key_in_frame(frame_stream_key(seed, frame), row, column);
}

// The generator of one key: state and stream selector both derived from the hash.
inline pcg32 pixel_stream(std::uint64_t key) { return pcg32(key, splitmix64(key ^ 0x5851f42d4c957f2dULL)); }

// Uniform in (0, 1) with 53 random bits, from two 32-bit outputs (never 0, so log() is safe).
inline double uniform_open01(pcg32& rng) {
  const std::uint64_t hi = rng() >> 5, lo = rng() >> 6;  // 27 + 26 bits
  return (static_cast<double>((hi << 26) | lo) + 0.5) * (1.0 / 9007199254740992.0);
}

// One uniform in (0, 1) from a key alone, 53 bits: a counter-based draw (a hash of the key, no
// generator state), for a pixel that needs exactly one variate. The extra finaliser round makes it
// independent of pixel_stream(key), which the same key seeds.
inline double keyed_uniform(std::uint64_t key) {
  return (static_cast<double>(splitmix64(key ^ 0x6b65796564753031ULL) >> 11) + 0.5) * (1.0 / 9007199254740992.0);
}

// Standard normal by Box-Muller (one value per call; two uniforms). Library-independent.
inline double standard_normal(pcg32& rng) {
  const double u1 = uniform_open01(rng), u2 = uniform_open01(rng);
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(6.283185307179586 * u2);
}

// The ls-conventional pixel array draws its Poisson counts and its normal pair with
// systemc/common/poisson_sampler.h (faster, library-independent); the other kernels use the above.

}  // namespace rangesim::systemc
