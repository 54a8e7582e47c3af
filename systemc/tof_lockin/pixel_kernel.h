#pragma once
// The tof-lockin photogate pixel as a plain C++ kernel.
#include "systemc/tof_lockin/kernel_types.h"

namespace rangesim::systemc::lockin {

// ---------------------------------------------------------------- photogate
// pixel
class LockinPixelKernel {
 public:
  LockinPixelKernel() = default;
  // Mean electrons generated on the photogate over [t_a, t_b] of period
  // `period` (seconds from the period start): signal eta I_s x light of the
  // pulses 0 .. period (a tail past T_rep reaches the next period), deep
  // electrons (1-eta) I_s T0 / T_rep, background.
  static double generated_e(const TofLockinConfig& cfg, const LockinPixelStimulus& s, bool led_on, double t_a,
                            double t_b, long long period, double time_step_s);
  // The same window summed over the n periods of a frame (aggregation).
  static double frame_generated_e(const TofLockinConfig& cfg, const LockinPixelStimulus& s, bool led_on, double t_a,
                                  double t_b, long long n, double time_step_s);
  // Noise amplitudes of the reset, fixed per configuration (computed once, not
  // per pixel and frame).
  struct ResetNoise {
    double ktc_fd_V[2] = {0, 0};  // kTC rms on FD1 / FD2, at the FD
    double read_V = 0;            // read noise rms per sample
    double offset_e[2] = {0, 0};  // mean offset charge C V_offset / q per FD (0: its shot noise off)
    static ResetNoise of(const TofLockinConfig& cfg);
  };
  // Reset of both FDs at the frame start; draws kTC and read noise (always
  // consumed).
  void reset(const ResetNoise& n, const LockinSimOptions& o, std::uint64_t frame, std::uint32_t row,
             std::uint32_t column);
  // Photogate charge of the open window recomputed from its opening time (tick
  // and skip agree bit for bit).
  void collect(const TofLockinConfig& cfg, const LockinSimOptions& o, const LockinPixelStimulus& s, bool led_on,
               double t_open, double t_now, long long period);
  // Closing edge of window w: TX1 / TX2 move the photogate charge into FD1 /
  // FD2; TXD drains it, (1 - eps) / 2 leaking into each FD, plus the dark
  // charge of the period on each FD.
  // The pixel's tap gains and dark-current offsets (fixed pattern) come with its stimulus.
  void transfer(const TofLockinConfig& cfg, const LockinSimOptions& o, const LockinPixelStimulus& s, int window,
                double period_s);
  // Aggregation: a frame's periods in one event, mean total m[k] per tap (all
  // windows and dark).
  void aggregate(const LockinSimOptions& o, const double m_total[2]);
  // ADC input of tap k: A_sf min(q (N + n_off - <n_off>) / C + V_offset + v_kTC, V_sat) + v_read.
  double adc_input_V(const TofLockinConfig& cfg, int tap) const;
  double fd_e(int tap) const { return fd_e_[tap]; }

 private:
  double draw_poisson(const LockinSimOptions& o, double mean);
  double fd_e_[2] = {0, 0};          // electrons on FD1 / FD2 (integer-valued with noise)
  double pg_e_ = 0;                  // mean electrons on the photogate in the open window
  double ktc_V_[2] = {0, 0};         // kTC reset noise on each FD (at the FD)
  double read_V_[2] = {0, 0};        // read noise of each tap's sample
  double offset_dev_e_[2] = {0, 0};  // offset charge of this frame minus its mean (its shot noise)
  pcg32 rng_;                        // the pixel's stream for this frame
};

}  // namespace rangesim::systemc::lockin
