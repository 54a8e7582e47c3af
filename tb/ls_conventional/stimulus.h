#pragma once
// Stimulus generator of ls-conventional, part of the installed verification kit
// (rangesim::cosim_kit): the random scenes rangesim's own readout co-simulation drives
// (tb/ls_conventional/cosim_harness.h), as a StimulusSource of the clock-level pixel array
// (systemc/ls_conventional/pixel_array_kernel.h), so a user's testbench can drive the same scenes
// into their readout and into rangesim's reference kernels. The same seed gives the same scenes.
#include <cmath>
#include <cstdint>
#include <random>

#include "systemc/ls_conventional/frame_stimulus.h"

namespace rangesim::tb {

// Random scene per frame access, drawn from (seed, frame) so it does not depend on call order:
// rows without beam, signal and background log-uniform over the evaluation grid's span, spot
// centres anywhere on the row (edges included).
inline systemc::StimulusSource random_ls_conventional_scenes(std::uint64_t seed, int rows, int columns) {
  return [=](std::uint64_t frame, systemc::FrameStimulus& out) {
    std::seed_seq seq{static_cast<std::uint32_t>(seed), static_cast<std::uint32_t>(seed >> 32),
                      static_cast<std::uint32_t>(frame), static_cast<std::uint32_t>(frame >> 32)};
    std::mt19937_64 rng(seq);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    out.rows.assign(static_cast<std::size_t>(rows), {});
    for (auto& r : out.rows) {
      const bool beam = u(rng) >= 0.1;
      r.signal_V = beam ? std::pow(10.0, -3.0 + 3.2 * u(rng)) : 0.0;  // 1 mV .. 1.6 V
      r.background_V = std::pow(10.0, -3.0 + 2.7 * u(rng));           // 1 mV .. 0.5 V
      r.centre_px = -0.5 + columns * u(rng);
    }
  };
}

}  // namespace rangesim::tb
