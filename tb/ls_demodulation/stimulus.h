#pragma once
// Stimulus generator of ls-demodulation, part of the installed verification kit
// (rangesim::cosim_kit): the random setups rangesim's own readout co-simulation draws
// (tb/ls_demodulation/cosim_harness.h), so a user's testbench can drive the same kind of frames
// into their sequencer and into rangesim's reference kernel (systemc/ls_demodulation/). The same
// generator state gives the same setup.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>

#include "core/ls_demodulation/config.h"
#include "systemc/ls_demodulation/sensor_kernel.h"

namespace rangesim::tb {

struct LsDemodulationSetup {
  LsDemodulationConfig cfg;
  systemc::DemodStimulus stim;
  long long frames = 1;
};

// The config's array width and readout (the instance's COLUMNS, ADDRESS_BITS, SEARCH_CYCLES)
// with the rest drawn within the preset's ranges and reduced: 2..6 rows, K = 1..3 decisions, N = 1..5
// correlation periods of 4..40 cycles (f0 = clock / period), a sheet beam 1..4 columns wide at
// a random column per row, beam 0.74 pA..1.1 nA and background 0.1 pA..10 nA log-uniform.
inline LsDemodulationSetup random_ls_demodulation_setup(const LsDemodulationConfig& base, std::uint64_t cycles,
                                                        std::mt19937_64& rng) {
  LsDemodulationSetup s;
  s.cfg = base;
  auto ui = [&](int a, int b) { return std::uniform_int_distribution<int>(a, b)(rng); };
  std::uniform_real_distribution<double> u(0.0, 1.0);
  LsDemodulationConfig& c = s.cfg;
  c.pixel.rows = ui(2, 6);
  const int period = 2 * ui(2, 20);
  c.modulation.frequency_Hz = c.readout.clock_Hz / period;
  c.correlator.cycles = ui(1, 5);
  c.pixel.integration_time_s = c.correlator.cycles / c.modulation.frequency_Hz;
  c.grid.detections = ui(1, 3);
  const int n = c.pixel.rows * c.pixel.columns;
  s.stim.beam_A.assign(static_cast<size_t>(n), 0.0);
  s.stim.background_A.assign(static_cast<size_t>(n), 0.0);
  for (int r = 0; r < c.pixel.rows; ++r) {
    const int c0 = ui(0, c.pixel.columns - 1), width = ui(1, 4);
    const double beam = 7.4e-13 * std::pow(1.11e-9 / 7.4e-13, u(rng));
    for (int col = 0; col < c.pixel.columns; ++col) {
      const size_t i = static_cast<size_t>(r) * c.pixel.columns + col;
      s.stim.background_A[i] = 1e-13 * std::pow(1e5, u(rng));
      if (col >= c0 && col < c0 + width) s.stim.beam_A[i] = beam;
    }
  }
  const long long frame_cycles = c.grid.detections * (static_cast<long long>(period) * c.correlator.cycles + 1 +
                                                      static_cast<long long>(c.pixel.rows) * c.readout.row_cycles);
  s.frames = std::clamp<long long>((static_cast<long long>(cycles) + frame_cycles - 1) / frame_cycles, 1, 65535);
  return s;
}

}  // namespace rangesim::tb
