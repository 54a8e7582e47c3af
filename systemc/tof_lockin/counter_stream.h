#pragma once
// A counter-based random stream for the tof-lockin kernels' merged frame draws
// (docs/tof-lockin-clock.md, "Noise"): word i of the stream keyed k is a pure function of (k, i),
// SplitMix64's output (G. L. Steele, D. Lea, C. H. Flood, "Fast splittable pseudorandom number
// generators", OOPSLA 2014):
//   word(i) = mix64(seed + (i + 1) gamma),  seed = mix64(k),  gamma = an odd mixed gamma of k.
// Every stream has its own gamma (the paper's split), so two streams are not shifts of each other.
// No state but the counter: the words of many streams (trials, pixels) can be computed side by
// side, several per SIMD register, and a draw never waits for the previous one of its stream.
#include <cstdint>

#include "systemc/common/random_stream.h"

namespace rangesim::systemc::lockin {

class CounterStream {
 public:
  CounterStream() = default;
  explicit CounterStream(std::uint64_t key) : seed_(splitmix64(key)), gamma_(mix_gamma(key)) {}
  // From a key that is already a SplitMix64 hash (saves one mix).
  static CounterStream from_hash(std::uint64_t hashed_key) {
    CounterStream s;
    s.seed_ = hashed_key, s.gamma_ = mix_gamma(hashed_key);
    return s;
  }

  // The next word (the counter advances).
  std::uint64_t next() { return word(counter_++); }
  // Continue from word i (a frame's words start at frame << 32).
  void seek(std::uint64_t i) { counter_ = i; }
  // Word i, without touching the counter.
  std::uint64_t word(std::uint64_t i) const { return mix64(seed_ + (i + 1) * gamma_); }
  std::uint64_t counter() const { return counter_; }

  // SplitMix64's mixing function (variant 13 of D. Stafford's finalisers), a bijection.
  static std::uint64_t mix64(std::uint64_t z) {
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }

 private:
  // The paper's mixGamma: odd, and with enough bit transitions to mix well.
  static std::uint64_t mix_gamma(std::uint64_t key) {
    std::uint64_t z = (mix64(key ^ 0x9e3779b97f4a7c15ULL) ^ 0x6a09e667f3bcc909ULL) | 1ULL;
    if (popcount(z ^ (z >> 1)) < 24) z ^= 0xaaaaaaaaaaaaaaaaULL;
    return z;
  }
  // Bits set (SWAR: the x86-64 baseline has no popcnt instruction, and a library call costs more).
  static int popcount(std::uint64_t x) {
    x -= (x >> 1) & 0x5555555555555555ULL;
    x = (x & 0x3333333333333333ULL) + ((x >> 2) & 0x3333333333333333ULL);
    x = (x + (x >> 4)) & 0x0f0f0f0f0f0f0f0fULL;
    return static_cast<int>((x * 0x0101010101010101ULL) >> 56);
  }
  std::uint64_t seed_ = 0, gamma_ = 1, counter_ = 0;
};

// Uniform in (0, 1) from the top 53 bits of a word (never 0, so log() is safe).
inline double open01(std::uint64_t w) { return (static_cast<double>(w >> 11) + 0.5) * (1.0 / 9007199254740992.0); }

// uniform_open01 for this stream, so the shared samplers (systemc/common/poisson_sampler.h) draw from it.
inline double uniform_open01(CounterStream& s) { return open01(s.next()); }

}  // namespace rangesim::systemc::lockin
