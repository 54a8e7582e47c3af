#pragma once
// Clock-level kernels of tof-lockin (thesis [12]): plain C++, explicit state,
// tick / event skipping. docs/tof-lockin-clock.md describes the schedule, the
// noise draws and the tests.
//
//   LockinGateKernel     lock-in gate timing generator: PHASE1 (TX1), PHASE2
//   (TX2), PHASE3 (TXD),
//                        light pulse emitted over [0, T0) of every period,
//                        N_acc periods a frame
//   LockinPixelKernel    photogate pixel: charge collected in the open window
//   (pulse overlap from
//                        the golden cumulative pulse area, background, deep
//                        electrons), transferred into FD1 / FD2 / drain at the
//                        window's closing edge; noise from a counter-based
//                        stream keyed (seed, frame, row, column)
//   LockinColumnAdcKernel column ADC: conversion cycles counted, truncating
//   code floor(V / LSB) TofLockinSensorKernel readout sequencer + array + ADC:
//   frames (LED frame, ambient frame),
//                        accumulation, row-by-row readout, range reconstruction
//                        (eq. 2.25)
#include <cstdint>
#include <string>
#include <vector>

#include <pcg_random.hpp>

#include "core/tof_lockin/config.h"

namespace rangesim::systemc::lockin {

// Phases of a frame in schedule order (0 = idle / done).
enum class LockinPhase : int {
  Idle = 0,
  Phase1 = 1,
  Phase2 = 2,
  Phase3 = 3,
  AdcConversion = 4,
  Output = 5
};
const char *phase_name(LockinPhase p);
inline constexpr int kPhaseCount = 5; // Phase1 .. Output

// Fidelity knobs.
struct LockinSimOptions {
  bool noise = true; // shot, kTC, read noise on (dark charge is always present
                     // as its mean)
  bool event_skipping =
      true; // advance to the next gate edge / conversion end instead of ticking
  bool aggregate =
      false; // with event_skipping: one event per accumulation phase (N_acc
             // identical periods summed; Poisson of the total mean, exact)
  std::uint64_t seed = 1; // key of the noise streams
  // 0: pulse/gate overlaps in closed form (exact). > 0: the pulse shape integrated numerically
  // at this step (golden::pulse_area_between_s): error falls and cost rises as it shrinks.
  double time_step_s = 0;
};

// Per-pixel stimulus from the scene.
struct LockinPixelStimulus {
  double signal_A = 0;     // signal photocurrent during the received pulse
  double background_A = 0; // constant background photocurrent
  double delay_s = 0;      // round-trip delay T_D = 2 L / c
};

// ---------------------------------------------------------------- gate timing
// generator
class LockinGateKernel {
public:
  explicit LockinGateKernel(
      const TofLockinConfig
          &cfg); // throws UserError if T_rep is off the clock grid
  void start();  // first cycle of PHASE1 of accumulation 0
  bool done() const { return acc_ >= n_acc_; }
  LockinPhase phase() const;
  bool tx1() const { return !done() && cyc_ < t0_; }
  bool tx2() const { return !done() && cyc_ >= t0_ && cyc_ < 2 * t0_; }
  bool txd() const { return !done() && cyc_ >= 2 * t0_; }
  bool light() const { return tx1(); } // emitted pulse [0, T0) of each period
  long long cycle_in_period() const { return cyc_; }
  long long accumulation() const { return acc_; }
  long long cycles_to_edge()
      const; // cycles until the gate pattern changes (>= 1 unless done)
  // Advances n cycles, 1 <= n <= cycles_to_edge(); returns true if a window
  // closed at the end.
  bool advance(long long n);
  // Finishes all remaining periods at once (aggregation); returns the cycles
  // skipped.
  long long finish_all();
  long long t0_cycles() const { return t0_; }
  long long period_cycles() const { return period_; }
  long long accumulations() const { return n_acc_; }
  // Edges of window w (0 = PHASE1, 1 = PHASE2, 2 = PHASE3) in cycles from the
  // period start.
  long long window_open(int w) const {
    return w == 0 ? 0 : w == 1 ? t0_ : 2 * t0_;
  }
  long long window_close(int w) const {
    return w == 0 ? t0_ : w == 1 ? 2 * t0_ : period_;
  }

private:
  long long t0_;      // T0 in gate-clock cycles
  long long period_;  // T_rep = T0 / duty in gate-clock cycles
  long long n_acc_;   // accumulations per frame
  long long acc_ = 0; // current accumulation
  long long cyc_ = 0; // cycle within the period
};

// ---------------------------------------------------------------- photogate
// pixel
class LockinPixelKernel {
public:
  LockinPixelKernel() = default;
  // Mean electrons generated on the photogate over [t_a, t_b] of period
  // `period` (seconds from the period start): signal eta I_s x light of the
  // pulses 0 .. period (a tail past T_rep reaches the next period), deep
  // electrons (1-eta) I_s T0 / T_rep, background.
  static double generated_e(const TofLockinConfig &cfg,
                            const LockinPixelStimulus &s, bool led_on,
                            double t_a, double t_b, long long period,
                            double time_step_s);
  // The same window summed over the n periods of a frame (aggregation).
  static double frame_generated_e(const TofLockinConfig &cfg,
                                  const LockinPixelStimulus &s, bool led_on,
                                  double t_a, double t_b, long long n,
                                  double time_step_s);
  // Noise amplitudes of the reset, fixed per configuration (computed once, not
  // per pixel and frame).
  struct ResetNoise {
    double ktc_fd_V[2] = {0, 0}; // kTC rms on FD1 / FD2, at the FD
    double read_V = 0;           // read noise rms per sample
    static ResetNoise of(const TofLockinConfig &cfg);
  };
  // Reset of both FDs at the frame start; draws kTC and read noise (always
  // consumed).
  void reset(const ResetNoise &n, const LockinSimOptions &o,
             std::uint64_t frame, std::uint32_t row, std::uint32_t column);
  // Photogate charge of the open window recomputed from its opening time (tick
  // and skip agree bit for bit).
  void collect(const TofLockinConfig &cfg, const LockinSimOptions &o,
               const LockinPixelStimulus &s, bool led_on, double t_open,
               double t_now, long long period);
  // Closing edge of window w: TX1 / TX2 move the photogate charge into FD1 /
  // FD2; TXD drains it, (1 - eps) / 2 leaking into each FD, plus the dark
  // charge of the period on each FD.
  void transfer(const TofLockinConfig &cfg, const LockinSimOptions &o,
                int window, double period_s);
  // Aggregation: a frame's periods in one event, mean total m[k] per tap (all
  // windows and dark).
  void aggregate(const LockinSimOptions &o, const double m_total[2]);
  // ADC input of tap k: A_sf min(q N / C + V_offset + v_kTC, V_sat) + v_read.
  double adc_input_V(const TofLockinConfig &cfg, int tap) const;
  double fd_e(int tap) const { return fd_e_[tap]; }

private:
  double draw_poisson(const LockinSimOptions &o, double mean);
  double fd_e_[2] = {0,
                     0}; // electrons on FD1 / FD2 (integer-valued with noise)
  double pg_e_ = 0;      // mean electrons on the photogate in the open window
  double ktc_V_[2] = {0, 0};  // kTC reset noise on each FD (at the FD)
  double read_V_[2] = {0, 0}; // read noise of each tap's sample
  pcg32 rng_;                 // the pixel's stream for this frame
};

// ---------------------------------------------------------------- column ADC
class LockinColumnAdcKernel {
public:
  explicit LockinColumnAdcKernel(const TofLockinConfig &cfg);
  long long code(double v) const; // floor(v / LSB) clipped to 0 .. 2^bits - 1
  double value_V(long long c) const { return static_cast<double>(c) * lsb_; }
  double lsb_V() const { return lsb_; }
  long long top_code() const { return codes_ - 1; }
  long long conversion_cycles() const { return conv_; }

private:
  double lsb_;      // full scale / 2^bits
  long long codes_; // 2^bits
  long long conv_;  // cycles of one conversion
};

// ---------------------------------------------------------------- sensor:
// sequencer + array
struct LockinFrameRecord {
  long long frame = 0; // frame index
  bool led_on = true;  // false: ambient frame
  long long cycles[kPhaseCount] =
      {}; // cycles per phase (gate clock for 1-3, readout clock for 4-5)
  double start_s = 0, end_s = 0; // simulated time
};

class TofLockinSensorKernel {
public:
  // sim_rows x sim_columns pixels (<= the configured array; the readout still
  // converts every row).
  TofLockinSensorKernel(const TofLockinConfig &cfg, const LockinSimOptions &opt,
                        int sim_rows, int sim_columns,
                        std::vector<LockinPixelStimulus> stimulus,
                        long long frames);
  // One event (or one cycle in tick mode). Returns false when all frames are
  // done.
  bool step();
  void run() {
    while (step()) {
    }
  }
  bool done() const { return frame_ >= frames_; }

  // State for ports / tracing.
  LockinPhase phase() const { return phase_; }
  const LockinGateKernel &gates() const { return gates_; }
  long long frame() const { return frame_; }
  int readout_row() const { return row_; }
  bool led_on() const;
  double time_s() const; // simulated time since the start
  long long gate_cycles() const { return gate_cycles_; }
  long long readout_cycles() const { return readout_cycles_; }
  long long events() const { return events_; }

  // Results.
  const std::vector<LockinFrameRecord> &frame_records() const {
    return records_;
  }
  // ADC code of tap k of pixel (r, c) in frame f.
  long long code(long long f, int r, int c, int k) const {
    return codes_[((static_cast<std::size_t>(f) * rows_ + r) * cols_ + c) * 2 +
                  k];
  }
  double adc_input_V(long long f, int r, int c, int k) const {
    return inputs_[((static_cast<std::size_t>(f) * rows_ + r) * cols_ + c) * 2 +
                   k];
  }
  long long range_maps() const; // complete range maps among the frames run
  // Range of pixel (r, c) in range map m (eq. 2.25), NaN if not detected /
  // saturated.
  double range_m(long long m, int r, int c) const;
  // Tap values a = V1 - V_cal (- ambient), b likewise, of range map m.
  void tap_values(long long m, int r, int c, double *a, double *b) const;
  int rows() const { return rows_; }
  int columns() const { return cols_; }
  const TofLockinConfig &config() const { return cfg_; }

private:
  void begin_frame();
  void end_accumulation_if_done();
  void convert_row(int r);

  TofLockinConfig cfg_;
  LockinSimOptions opt_;
  int rows_, cols_;
  std::vector<LockinPixelStimulus> stim_;
  long long frames_;
  LockinGateKernel gates_;
  LockinColumnAdcKernel adc_;
  std::vector<LockinPixelKernel> pixels_;
  LockinPixelKernel::ResetNoise reset_noise_;
  // Aggregation: each pixel's mean frame totals per tap, LED frame [1] and
  // ambient frame [0]; stimulus and gates are fixed, so computed once each.
  std::vector<double> frame_mean_e_[2]; // 2 per pixel (FD1, FD2)
  std::vector<long long> codes_; // per frame, pixel, tap
  std::vector<double> inputs_;   // ADC inputs, same layout
  std::vector<LockinFrameRecord> records_;
  LockinPhase phase_ = LockinPhase::Idle;
  long long frame_ = 0;
  int row_ = 0; // row in readout
  long long in_phase_ =
      0; // cycles spent in the current readout phase of the row
  long long gate_cycles_ = 0;    // total gate-clock cycles
  long long readout_cycles_ = 0; // total readout-clock cycles
  long long events_ = 0;         // steps taken
  bool started_ = false;
};

} // namespace rangesim::systemc::lockin
