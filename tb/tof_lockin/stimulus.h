#pragma once
// Stimulus generators of tof-lockin, part of the installed verification kit (rangesim::cosim_kit):
// the random setups rangesim's own co-simulation draws (tb/tof_lockin/cosim_harness.h and the
// block harnesses), so a user's testbench can drive the same kind of operations into their RTL
// and into rangesim's reference kernels (systemc/tof_lockin/). Each takes the generator by
// reference: the same seed gives the same draws as rangesim's built-in co-simulation.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "core/tof_lockin/config.h"
#include "systemc/tof_lockin/sensor_kernel.h"

namespace rangesim::tb {

// One readout run: configuration (a reduced array), the kernel's options and each pixel's light.
struct TofLockinSetup {
  TofLockinConfig cfg;
  systemc::lockin::LockinSimOptions sim;
  std::vector<systemc::lockin::LockinPixelStimulus> stim;  // [row * columns + column]
  long long frames = 2;
};

// Frames covering at least `cycles` (at least two; even with ambient subtraction), at most 65534.
inline long long tof_lockin_frames_for(const TofLockinConfig& c, std::uint64_t cycles) {
  const long long frame_cycles = c.gates.accumulations_per_frame * gate_period_cycles(c) +
                                 c.pixel.rows * (c.readout.adc_conversion_cycles + c.readout.output_cycles_per_row);
  long long frames = std::max<long long>(2, (static_cast<long long>(cycles) + frame_cycles - 1) / frame_cycles);
  if (c.readout.ambient_subtraction && frames % 2) ++frames;
  return std::min<long long>(frames, 65534);
}

// Signal 10 pA..1.5 nA and background 10 fA..10 nA log-uniform, delay within T0, per pixel.
inline std::vector<systemc::lockin::LockinPixelStimulus> random_tof_lockin_pixels(const TofLockinConfig& c,
                                                                                  std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<systemc::lockin::LockinPixelStimulus> v;
  for (int p = 0; p < c.pixel.rows * c.pixel.columns; ++p) {
    systemc::lockin::LockinPixelStimulus x;
    x.signal_A = 1e-11 * std::pow(150.0, u(rng));
    x.background_A = 1e-14 * std::pow(1e6, u(rng));
    x.delay_s = c.source.pulse_width_s * u(rng);
    v.push_back(x);
  }
  return v;
}

// The built-in target's setup: parameters within the preset ranges, reduced array: T0 1..10 gate
// cycles (10-100 ns at 100 MHz), duty 1/2..1/10, N_acc 1..50, 2..5 rows x 1..4 columns, 4..8-bit
// ADC with 2^bits..2^bits+3 conversion cycles, 2 x columns..+4 output cycles, ambient frames in
// 80 % of the runs; noise on; `cycles` rounded up to whole frames.
inline TofLockinSetup random_tof_lockin_setup(std::uint64_t cycles, std::uint64_t seed, std::mt19937_64& rng) {
  TofLockinSetup s;
  auto ui = [&](int a, int b) { return std::uniform_int_distribution<int>(a, b)(rng); };
  std::uniform_real_distribution<double> u(0.0, 1.0);
  TofLockinConfig& c = s.cfg;
  const int t0 = ui(1, 10), m = ui(2, 10);
  c.source.pulse_width_s = t0 / c.gates.clock_Hz;
  c.source.duty_cycle = 1.0 / m;
  c.gates.accumulations_per_frame = ui(1, 50);
  c.pixel.rows = ui(2, 5);
  c.pixel.columns = ui(1, 4);
  c.readout.adc_bits = ui(4, 8);
  c.readout.adc_conversion_cycles = (1LL << c.readout.adc_bits) + ui(0, 3);
  c.readout.output_cycles_per_row = 2 * c.pixel.columns + ui(0, 4);
  c.readout.ambient_subtraction = u(rng) < 0.8;
  s.sim.noise = true;
  s.sim.event_skipping = false;  // tick mode: one step per clock cycle
  s.sim.seed = seed;
  s.stim = random_tof_lockin_pixels(c, rng);
  s.frames = tof_lockin_frames_for(c, cycles);
  return s;
}

// A preset's setup: the preset's own timing, ADC and noise (`preset`, its config), on a reduced
// array of 2..5 rows x 1..max_columns columns (the rest of its rows and columns repeat these);
// each pixel's light as above; `cycles` rounded up to whole frames.
inline TofLockinSetup random_tof_lockin_setup(const TofLockinConfig& preset, int max_columns, std::uint64_t cycles,
                                              std::uint64_t seed, std::mt19937_64& rng) {
  TofLockinSetup s;
  s.cfg = preset;
  s.cfg.pixel.rows = std::uniform_int_distribution<int>(2, 5)(rng);
  s.cfg.pixel.columns = std::uniform_int_distribution<int>(1, max_columns)(rng);
  s.sim.noise = true;
  s.sim.event_skipping = false;
  s.sim.seed = seed;
  s.stim = random_tof_lockin_pixels(s.cfg, rng);
  s.frames = tof_lockin_frames_for(s.cfg, cycles);
  return s;
}

// lockin_gate_generator: gate parameters within the preset ranges, on the gate-clock grid (the
// kernel's rule): T0 1..32 cycles, duty 1/2..1/10, N_acc 1..64 at the default 100 MHz gate clock.
inline TofLockinConfig random_lockin_gate_generator_config(std::mt19937_64& rng) {
  TofLockinConfig cfg;
  const int t0 = std::uniform_int_distribution<int>(1, 32)(rng);
  const int m = std::uniform_int_distribution<int>(2, 10)(rng);
  cfg.source.pulse_width_s = t0 / cfg.gates.clock_Hz;
  cfg.source.duty_cycle = 1.0 / m;
  cfg.gates.accumulations_per_frame = std::uniform_int_distribution<int>(1, 64)(rng);
  return cfg;
}

// column_adc: one conversion. Resolution 1..12 bits, full scale 0.5..1.5 V, conversion cycles
// 2^bits .. 2^bits + 3 (single slope: at least one cycle per code), inputs over the whole range
// plus a little outside it (clipping), and exact code boundaries in 20 % of the draws.
struct ColumnAdcConversion {
  TofLockinConfig cfg;
  double v_in = 0;  // ADC input
};
inline ColumnAdcConversion random_column_adc_conversion(std::mt19937_64& rng) {
  ColumnAdcConversion c;
  std::uniform_real_distribution<double> u(0.0, 1.0);
  c.cfg.readout.adc_bits = std::uniform_int_distribution<int>(1, 12)(rng);
  c.cfg.readout.adc_full_scale_V = 0.5 + u(rng);
  c.cfg.readout.adc_conversion_cycles = (1LL << c.cfg.readout.adc_bits) + std::uniform_int_distribution<int>(0, 3)(rng);
  const double fs = c.cfg.readout.adc_full_scale_V;
  const double lsb = fs / std::ldexp(1.0, c.cfg.readout.adc_bits);
  if (u(rng) < 0.2) {  // on a code boundary
    c.v_in = lsb * std::uniform_int_distribution<int>(0, 1 << c.cfg.readout.adc_bits)(rng);
  } else {
    c.v_in = -0.05 * fs + 1.1 * fs * u(rng);
  }
  return c;
}

}  // namespace rangesim::tb
