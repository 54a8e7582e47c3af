#pragma once
// One SPAD pixel of tof-spad, event driven: photon arrivals of one row integration as an
// inhomogeneous Poisson process (Gaussian laser echo per laser cycle + uniform background + dark
// counts), Geiger firing with non-paralysable dead time (recharge), afterpulsing and timing jitter.
// The kernel jumps from arrival to arrival (exponential gaps for the uniform part, geometric
// skips over laser cycles without a signal photon), never per clock cycle.
//
// Randomness (systemc/random_stream.h): three counter-based streams per pixel, keyed by
// (seed ^ salt, frame, row, column): signal photons, uniform photons, SPAD (afterpulse + jitter).
// A switched-off source still consumes its draws, so switching one does not move the others.
#include <cstdint>
#include <limits>
#include <queue>
#include <vector>

#include "core/tof_spad_config.h"
#include "systemc/random_stream.h"

namespace rangesim::systemc::spad {

// What the scene puts on one pixel: PDE-weighted count rates (as in the preset) and the echo.
struct PixelRates {
  double signal_Hz = 0;      // signal detections per second before dead-time losses
  double background_Hz = 0;  // ambient detections per second before dead-time losses
  double round_trip_s = 0;   // echo centre 2 L / c
};

// Noise sources; none() leaves a delta echo with Poisson-many photons and nothing else.
struct SpadNoise {
  bool background = true;   // ambient photons
  bool dark = true;         // dark counts
  bool afterpulse = true;   // afterpulses after the dead time
  bool jitter = true;       // SPAD + front-end timing jitter
  bool pulse_width = true;  // Gaussian laser pulse (off: delta pulse)
  static SpadNoise none() { return {false, false, false, false, false}; }
};

class SpadPixelKernel {
 public:
  static constexpr double kNever = std::numeric_limits<double>::infinity();

  // `laser_cycles` periods of `cfg.laser` starting at t = 0 (the row's first START).
  SpadPixelKernel(const TofSpadConfig& cfg, const PixelRates& rates, const SpadNoise& noise, long long laser_cycles,
                  std::uint64_t seed, std::uint64_t frame, std::uint32_t row, std::uint32_t column);

  // Output time (s, from the first START) of the next avalanche, kNever when none is left.
  double peek() const { return next_avalanche_s_; }
  // Consumes the avalanche returned by peek() and finds the next one.
  void pop() { advance(); }

  long long avalanches() const { return avalanches_; }  // avalanches output so far (incl. afterpulses)
  long long photons() const { return photons_; }        // photon/dark arrivals so far (incl. lost in dead time)
  long long afterpulses() const { return afterpulses_; }

 private:
  void advance();
  void next_signal_cycle();
  void next_uniform();

  double period_s_, end_s_;           // laser period; end of the integration
  double signal_per_cycle_;           // mean signal photons per laser cycle
  double uniform_rate_Hz_;            // background + dark (switched)
  double round_trip_s_, pulse_sigma_s_, jitter_sigma_s_;  // echo centre, pulse sigma, jitter rms
  double dead_time_s_, afterpulse_p_, afterpulse_tau_s_;  // SPAD recharge and afterpulsing
  bool jitter_on_, afterpulse_on_;
  pcg32 signal_rng_, uniform_rng_, spad_rng_;  // the three keyed streams
  long long signal_cycle_ = -1;       // laser cycle of the buffered signal photons
  std::vector<double> signal_buf_;    // signal photon times of that cycle, descending (pop_back = earliest)
  double uniform_next_s_ = kNever;    // next uniform (background/dark) arrival
  std::priority_queue<double, std::vector<double>, std::greater<double>> afterpulse_q_;  // pending afterpulses
  double dead_until_s_ = -kNever;     // SPAD recharged at this time
  double next_avalanche_s_ = kNever;  // output time of the next avalanche
  long long avalanches_ = 0, photons_ = 0, afterpulses_ = 0;
};

}  // namespace rangesim::systemc::spad
