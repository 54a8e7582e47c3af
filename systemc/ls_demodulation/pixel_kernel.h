#pragma once
// Cycle kernel of one demodulating pixel of ls-demodulation (thesis [27]): plain C++, no SystemC.
//
// Chain (golden/ls_demodulation/front_end.h): LPF -> mirror subtraction -> log I-V -> two
// correlating integrators switched by MPY+/MPY-. The photocurrent is constant between clock edges
// where the beam or MPY switches, so the continuous-time parts are solved EXACTLY per piece with the
// golden per-segment solution (the LPF exponential and golden::log_integral of the log stage):
// stepping one clock cycle (tick) or a whole segment (event skipping, jump to the next MPY/beam
// edge) is the same piecewise-exponential solution, equal to rounding.
//
// Aggregation (default in the sensor kernel; `reset(..., aggregate = true)`): the N correlation
// periods of a window are identical (the LPF starts in its periodic steady state), so the window
// is one step of window_cycles(): the swings are golden::correlate_periodic's (N x one period),
// the shot noise one Gaussian draw per integrator with the summed variance of all its segments
// (a sum of independent Gaussians: exact). O(S + log N) time and memory per window.
// Per period (aggregate = false, and always when ticking): every segment of every period stepped.
//
// Noise (all from the counter-based stream of the pixel and decision, systemc/common/random_stream.h):
//   draws in this order at reset: kTC of C1, kTC of C2, fixed-pattern offset, the LPF's memory of
//   the shot noise before the window; then, per period, one Gaussian shot-noise charge per segment,
//   drawn at the segment's last edge with the closed-form variance of golden front_end (the same
//   backward recursion, so the sum of the per-segment draws has exactly golden's shot_var_V2);
//   aggregated, one draw for C1 and one for C2 at the window end. A switched-off source still
//   consumes its draw (except the shot draws).
#include <cstdint>
#include <optional>
#include <vector>

#include <pcg_random.hpp>

#include "core/ls_demodulation/config.h"
#include "golden/ls_demodulation/front_end.h"

namespace rangesim::systemc {

// Which noise sources are on (all on by default).
struct DemodNoiseSwitches {
  bool shot = true;           // photo/dark current shot noise through the chain
  bool ktc = true;            // kTC of C1 and C2 at the integrator reset
  bool read = true;           // frame-common read noise of the row (drawn by the sensor kernel)
  bool fixed_pattern = true;  // per-decision comparator offset (0 V rms in the preset)
  static DemodNoiseSwitches none() { return {false, false, false, false}; }
  bool any() const { return shot || ktc || read || fixed_pattern; }
};

// Clock schedule of one correlation window, shared by all pixels: segment boundaries in clock
// cycles (one correlation period, repeated `periods` times).
struct DemodWindowSchedule {
  std::vector<int> segment_cycles;  // cycles of each segment of one period (sum = period_cycles)
  std::vector<int> segment_branch;  // +1 MPY+ (C1), -1 MPY- (C2)
  int period_cycles = 0;            // clock / f0
  int periods = 0;                  // N correlation periods per decision
  double clock_Hz = 0;              // clock of the cycles
  long long window_cycles() const { return static_cast<long long>(period_cycles) * periods; }
};

// Builds the schedule; throws std::invalid_argument (naming the key) if an MPY or beam edge does
// not fall on a clock edge or N / f0 differs from the integration time by more than a cycle.
DemodWindowSchedule demod_window_schedule(const LsDemodulationConfig& cfg);

class DemodPixelKernel {
 public:
  DemodPixelKernel(const LsDemodulationConfig& cfg, const DemodWindowSchedule& sched);

  // Integrator reset at the window start for a pixel seeing beam-on current `beam_A` (square at
  // f0, source duty) over `background_A` (+ dark current); the LPF starts in its periodic steady
  // state (golden::lpf_periodic_start_A). Draws the reset noise from `rng` (consumed even if off).
  // `aggregate`: the window is one step (see above); otherwise segment by segment.
  void reset(double beam_A, double background_A, pcg32& rng, const DemodNoiseSwitches& noise, bool aggregate = false);

  // Advances `cycles` clock cycles (1 = tick; at most to the end of the current segment;
  // aggregated: exactly the whole window).
  void step(long long cycles);
  // Cycles to the next edge (the event-skipping jump: the segment's end, aggregated the window's
  // end), 0 at the window end.
  long long cycles_to_edge() const;
  bool window_done() const { return period_index_ >= sched_.periods; }
  bool aggregated() const { return aggregate_; }

  double plus_V() const { return plus_V_; }
  double minus_V() const { return minus_V_; }
  double diff_V() const { return plus_V_ - minus_V_; }  // V_out+ - V_out- (with noise)
  double lpf_A() const { return dc0_A_ + lpf_offset_A_; }
  const std::vector<golden::Segment>& period() const { return period_; }

 private:
  void begin_period();
  void end_segment();

  LsDemodulationConfig cfg_;                        // the pixel's parameters
  DemodWindowSchedule sched_;                       // segment boundaries in cycles
  std::vector<golden::Segment> period_;             // one correlation period (every period is the same)
  double dc0_A_ = 0;                                // I_dc of the period: the LPF is held as its offset from it
  bool aggregate_ = false;                          // the window in one step
  golden::CorrelatorOutput window_;                 // aggregated: golden's window (swings, variances, LPF end)
  std::optional<golden::PeriodicShotNoise> noise_;  // per period: the shot-noise recursion
  std::vector<double> shot_sd_V_;                   // per period: sd of each segment's shot-noise draw on D
  pcg32* rng_ = nullptr;                            // the pixel's stream during the window
  bool shot_ = false;                               // shot noise on
  long long period_index_ = 0;                      // current period
  std::size_t seg_index_ = 0;                       // current segment within the period
  long long seg_cycle_ = 0;                         // cycles done in the current segment
  double lpf_offset_A_ = 0;                         // I_avg - dc0_A_ now (exact lag under a huge background)
  double plus_V_ = 0;                               // V_out+ swing (C1)
  double minus_V_ = 0;                              // V_out- swing (C2)
};

}  // namespace rangesim::systemc
