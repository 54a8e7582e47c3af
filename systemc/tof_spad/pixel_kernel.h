#pragma once
// One SPAD pixel of tof-spad, event driven: photon arrivals of one row integration as an
// inhomogeneous Poisson process (Gaussian laser echo per laser cycle + uniform background + dark
// counts), Geiger firing with non-paralysable dead time (recharge), afterpulsing and timing jitter.
// The kernel jumps from arrival to arrival (exponential gaps for the uniform part, geometric
// skips over laser cycles without a signal photon), never per clock cycle.
//
// Times are relative (SpadTime): an integer laser cycle and a double offset within it, so the
// resolution of an arrival is ulp(period), not ulp(integration time), however long the
// integration (docs/numerical-stability.md).
//
// Randomness (systemc/common/random_stream.h): three counter-based streams per pixel, keyed by
// (seed ^ salt, frame, row, column): signal photons, uniform photons, SPAD (afterpulse + jitter).
// A switched-off source still consumes its draws, so switching one does not move the others.
#include <cstdint>
#include <limits>
#include <queue>
#include <vector>

#include "core/tof_spad/config.h"
#include "systemc/common/random_stream.h"

namespace rangesim::systemc::spad {

// A further return of the pulse on a pixel: a second path (multipath) or, through the point
// spread and crosstalk, a neighbour's surface.
struct SpadEcho {
  double signal_Hz = 0;     // its detections per second before dead-time losses
  double round_trip_s = 0;  // its centre
};

// What the scene puts on one pixel: PDE-weighted count rates (as in the preset) and the echo.
struct PixelRates {
  double signal_Hz = 0;               // signal detections per second before dead-time losses
  double background_Hz = 0;           // ambient detections per second before dead-time losses
  double round_trip_s = 0;            // echo centre 2 L / c
  double dark_extra_Hz = 0;           // fixed pattern: this pixel's dark count rate minus the preset's
  std::vector<SpadEcho> echoes = {};  // further returns (usually none)
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

// A time of the row integration: laser cycle (0 = the row's first START) and offset within it,
// normalised to 0 <= offset_s < period (a negative cycle: before the first START).
struct SpadTime {
  long long cycle = 0;
  double offset_s = 0;
  bool operator<(const SpadTime& o) const { return cycle != o.cycle ? cycle < o.cycle : offset_s < o.offset_s; }
  bool operator>(const SpadTime& o) const { return o < *this; }
  bool operator==(const SpadTime& o) const { return cycle == o.cycle && offset_s == o.offset_s; }
  bool operator<=(const SpadTime& o) const { return !(o < *this); }
  bool never() const { return cycle == std::numeric_limits<long long>::max(); }
  static SpadTime never_time() { return {std::numeric_limits<long long>::max(), 0.0}; }
  static SpadTime earliest_time() { return {std::numeric_limits<long long>::min(), 0.0}; }
};

class SpadPixelKernel {
 public:
  // `laser_cycles` periods of `cfg.laser` starting at t = 0 (the row's first START).
  SpadPixelKernel(const TofSpadConfig& cfg, const PixelRates& rates, const SpadNoise& noise, long long laser_cycles,
                  std::uint64_t seed, std::uint64_t frame, std::uint32_t row, std::uint32_t column);

  // Output time of the next avalanche (never() when none is left).
  SpadTime peek() const { return next_avalanche_; }
  bool done() const { return next_avalanche_.never(); }
  // The same in seconds from the first START (diagnostics: rounds to ulp of the absolute time).
  double peek_s() const { return static_cast<double>(next_avalanche_.cycle) * period_s_ + next_avalanche_.offset_s; }
  // Consumes the avalanche returned by peek() and finds the next one.
  void pop() { advance(); }

  long long avalanches() const { return avalanches_; }  // avalanches output so far (incl. afterpulses)
  long long photons() const { return photons_; }        // photon/dark arrivals so far (incl. lost in dead time)
  long long afterpulses() const { return afterpulses_; }

 private:
  void advance();
  void next_signal_cycle();
  void next_uniform();
  // t + dt_s, normalised into its cycle (never() past any representable cycle).
  SpadTime shifted(SpadTime t, double dt_s) const;

  double period_s_;                                       // laser period
  long long laser_cycles_;                                // end of the integration (cycle index past the last)
  double signal_per_cycle_;                               // mean signal photons per laser cycle (all echoes)
  std::vector<double> echo_share_, echo_delay_s_;         // further echoes: cumulative share of the photons, centre
  double uniform_rate_Hz_;                                // background + dark (switched)
  double round_trip_s_, pulse_sigma_s_, jitter_sigma_s_;  // echo centre, pulse sigma, jitter rms
  double dead_time_s_, afterpulse_p_, afterpulse_tau_s_;  // SPAD recharge and afterpulsing
  bool jitter_on_, afterpulse_on_;
  pcg32 signal_rng_, uniform_rng_, spad_rng_;  // the three keyed streams
  long long signal_cycle_ = -1;                // laser cycle of the buffered signal photons
  std::vector<SpadTime> signal_buf_;           // signal photon times of that cycle, descending (pop_back = earliest)
  SpadTime uniform_next_ = SpadTime::never_time();  // next uniform (background/dark) arrival
  bool uniform_started_ = false;                    // the first uniform gap is drawn from t = 0
  std::priority_queue<SpadTime, std::vector<SpadTime>, std::greater<SpadTime>> afterpulse_q_;  // pending afterpulses
  SpadTime dead_until_ = SpadTime::earliest_time();   // SPAD recharged at this time
  SpadTime next_avalanche_ = SpadTime::never_time();  // output time of the next avalanche
  long long avalanches_ = 0, photons_ = 0, afterpulses_ = 0;
};

}  // namespace rangesim::systemc::spad
