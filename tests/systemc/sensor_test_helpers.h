#pragma once
// Shared by the ls-conventional sensor tests: small configurations and stimulus sources.
#include <cstdint>
#include <memory>
#include <random>
#include <vector>

#include "core/ls_conventional/config.h"
#include "systemc/ls_conventional/frame_stimulus.h"

namespace rangesim::systemc::test {

// The preset defaults (core/ls_conventional/config.h mirrors presets/ls-conventional.toml) with
// a smaller array for fast tests.
inline LsConventionalConfig small_config(int rows = 24, int columns = 96, int samplings = 4) {
  LsConventionalConfig c;
  c.pixel.read_noise_V = 0.3e-3;  // as the preset
  c.pixel.rows = rows;
  c.pixel.columns = columns;
  c.multisampling.samplings = samplings;
  int bits = 1;
  while ((1 << bits) < columns) ++bits;
  c.timing.address_bits = bits;
  c.search.columns = columns;
  c.search.address_bits = bits;
  c.search.addresses_per_sampling = c.timing.addresses_per_sampling;
  return c;
}

// Random stimulus per (frame, row), itself keyed so it does not depend on call order: signal
// log-uniform in [sig_lo, sig_hi], background log-uniform in [bg_lo, bg_hi], centre uniform over
// the row (2 px from the ends); every 9th row dark (no beam).
struct RandomStimulus {
  std::uint64_t seed = 5;
  double sig_lo = 0.005, sig_hi = 1.5, bg_lo = 1e-4, bg_hi = 0.05;
  int columns = 96;
  void operator()(std::uint64_t frame, FrameStimulus& out) const {
    for (std::size_t r = 0; r < out.rows.size(); ++r) {
      std::mt19937_64 rng(seed * 1000003ULL + frame * 7919ULL + r);
      std::uniform_real_distribution<double> u(0, 1);
      RowIllumination& row = out.rows[r];
      row.signal_V = (r % 9 == 8) ? 0.0 : sig_lo * std::pow(sig_hi / sig_lo, u(rng));
      row.background_V = bg_lo * std::pow(bg_hi / bg_lo, u(rng));
      row.centre_px = 2 + (columns - 5) * u(rng);
    }
  }
};

// RandomStimulus with the spot's signal from 0.011 V to sig_hi: near the threshold, the noise decides.
inline RandomStimulus near_threshold(double sig_hi = 0.05) {
  RandomStimulus s;
  s.sig_lo = 0.011;
  s.sig_hi = sig_hi;
  return s;
}

// Every row and frame the same illumination.
struct UniformStimulus {
  RowIllumination row;
  void operator()(std::uint64_t, FrameStimulus& out) const {
    for (auto& r : out.rows) r = row;
  }
};

}  // namespace rangesim::systemc::test
