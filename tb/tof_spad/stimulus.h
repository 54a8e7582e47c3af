#pragma once
// Stimulus generators of tof-spad, part of the installed verification kit (rangesim::cosim_kit):
// the random setups rangesim's own co-simulation draws (tb/tof_spad/cosim_harness.h, targets
// tof-spad and tdc), so a user's testbench can drive the same kind of rows into their TDC group
// and into rangesim's reference kernels (systemc/tof_spad/). The same seed gives the same draws
// as rangesim's built-in co-simulation.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

#include "core/tof_spad/config.h"
#include "systemc/tof_spad/pixel_kernel.h"
#include "systemc/tof_spad/sensor_kernel.h"

namespace rangesim::tb {

// Rows of one TDC group: the configuration and each pixel's rates.
struct TofSpadSetup {
  TofSpadConfig cfg;
  int rows = 1;
  std::vector<systemc::spad::PixelRates> rates;  // [row * columns_per_tdc + column]
};

// Within the preset's ranges, scaled so a row fits a short run: TDC LSB 0.25-2 ns, laser
// 20-80 MHz (Np 7..200 codes), full range 0.6-1.2 laser periods (overflow happens), TDC busy
// 0-2 periods, dead time 5-50 ns, L = 20..150 laser cycles; 2..3 rows (1 with high_rates). Rates:
// signal and background 0.1-20 MHz per pixel (high_rates: 5-50 MHz, to crowd the arbitration).
// The group's width is base.tdc.columns_per_tdc.
inline TofSpadSetup random_tof_spad_setup(const TofSpadConfig& base, std::mt19937_64& rng, bool high_rates) {
  TofSpadSetup s;
  s.cfg = base;
  const int cpt = base.tdc.columns_per_tdc;
  std::uniform_real_distribution<double> u(0.0, 1.0);
  auto logu = [&](double a, double b) { return a * std::pow(b / a, u(rng)); };
  TofSpadConfig& c = s.cfg;
  c.tdc.lsb_s = logu(0.25e-9, 2e-9);
  c.laser.repetition_rate_Hz = logu(20e6, 80e6);
  const double period = 1.0 / c.laser.repetition_rate_Hz;
  c.tdc.full_range_s = period * (0.6 + 0.6 * u(rng));
  c.tdc.busy_time_s = 2.0 * period * u(rng);
  c.spad.dead_time_s = logu(5e-9, 50e-9);
  const long long L = std::uniform_int_distribution<int>(20, 150)(rng);
  c.histogram.integration_time_s = static_cast<double>(L) / c.laser.repetition_rate_Hz;
  s.rows = high_rates ? 1 : std::uniform_int_distribution<int>(2, 3)(rng);
  for (int i = 0; i < s.rows * cpt; ++i) {
    systemc::spad::PixelRates p;
    p.signal_Hz = high_rates ? logu(5e6, 50e6) : logu(1e5, 2e7);
    p.background_Hz = high_rates ? logu(5e6, 50e6) : logu(1e5, 2e7);
    p.round_trip_s = period * u(rng);
    s.rates.push_back(p);
  }
  return s;
}

// Rows of random setups (seeded with `seed`) until `cycles` are covered, the timing of the first;
// past `max_rows` the integration gets longer instead (more laser cycles per row). `cpt`: the
// group's columns (tdc.columns_per_tdc of base).
inline TofSpadSetup random_tof_spad_rows(const TofSpadConfig& base, int cpt, long long max_rows, std::uint64_t cycles,
                                         std::uint64_t seed, bool high_rates) {
  std::mt19937_64 rng(seed);
  TofSpadSetup s = random_tof_spad_setup(base, rng, high_rates);
  const systemc::spad::TofSpadKernel k(s.cfg, 1, cpt, {});
  const long long row = k.laser_cycles() * k.phase_bins() + k.readout_words_per_row() * k.cycles_per_word();
  const long long want_rows = std::max<long long>((static_cast<long long>(cycles) + row - 1) / row, 1);
  const long long rows = std::min<long long>(want_rows, max_rows);
  while (s.rows < rows) {
    const TofSpadSetup more = random_tof_spad_setup(base, rng, high_rates);
    s.rates.insert(s.rates.end(), more.rates.begin(), more.rates.end());
    s.rows += more.rows;
  }
  s.rows = static_cast<int>(std::min<long long>(s.rows, max_rows));
  s.rates.resize(static_cast<size_t>(s.rows) * cpt);
  if (want_rows > max_rows) {
    const long long stretch = (want_rows + max_rows - 1) / max_rows;
    s.cfg.histogram.integration_time_s *= static_cast<double>(stretch);
  }
  return s;
}

}  // namespace rangesim::tb
