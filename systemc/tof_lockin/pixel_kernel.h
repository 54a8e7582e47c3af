#pragma once
// The tof-lockin photogate pixel as a plain C++ kernel.
#include <algorithm>

#include "systemc/tof_lockin/frame_draw.h"
#include "systemc/tof_lockin/kernel_types.h"
#include "systemc/tof_lockin/normal_ziggurat.h"

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
  // The conversion of FD electrons to the ADC input, fixed per configuration.
  struct Readout {
    double a_sf = 1;                 // source-follower gain
    double volts_per_e[2] = {0, 0};  // A_sf q / C_k (golden::volts_per_electron)
    double offset_V = 0, sat_V = 0;  // V_offset and V_sat on the FD
    static Readout of(const TofLockinConfig& cfg);
  };
  // Reset of both FDs at the frame start; draws kTC and read noise (always
  // consumed), or with `merged` (an aggregated frame's merged draws, frame_draw.h) only places
  // the pixel's counter-based stream, keyed (seed, row, column), at the frame's words
  // (frame << 32): aggregate_merged draws everything.
  void reset(const ResetNoise& n, const LockinSimOptions& o, std::uint64_t frame, std::uint32_t row,
             std::uint32_t column, bool merged = false);
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
  // The same frame by its merged draws (frame_draw.h): one count and the normal noise per tap,
  // from the counter-based stream placed at the reset.
  void aggregate_merged(const TapFrameLaw law[2]) { draw_merged(stream_, law, fd_e_, ktc_V_, read_V_); }
  // reset(n, o, frame, row, column, true) for the merged draws.
  void reset_merged(const LockinSimOptions& o, std::uint64_t frame, std::uint32_t row, std::uint32_t column) {
    clear();
    if (o.noise) place_stream(o.seed, frame, row, column);
  }
  // ADC input of tap k: A_sf min(q (N + n_off - <n_off>) / C + V_offset + v_kTC, V_sat) + v_read.
  double adc_input_V(const TofLockinConfig& cfg, int tap) const;
  // The same with the constants computed once (identical arithmetic, so identical bits).
  double adc_input_V(const Readout& r, int tap) const {
    return input_V(r, tap, fd_e_[tap], offset_dev_e_[tap], ktc_V_[tap], read_V_[tap]);
  }

  // The merged draws as functions of their inputs alone, so a Monte Carlo trial can take a pixel's
  // frames without its state (bit for bit what aggregate_merged and adc_input_V give):
  // the stream of pixel (row, column) for `seed`, to be placed at frame << 32 ...
  static CounterStream merged_stream(std::uint64_t seed, std::uint32_t row, std::uint32_t column) {
    // One mix of the seed with the pixel folded in (an odd multiple, so distinct pixels differ),
    // then the stream's gamma from that hash.
    return CounterStream::from_hash(
        splitmix64(seed ^ (((static_cast<std::uint64_t>(row) << 32) | column) * 0xd1b54a32d192ed03ULL)));
  }
  // ... the frame's counts and normals (electrons on the FDs without the offset charge's mean,
  // kTC at the FD, read noise, or both as one where V_sat cannot be reached) ...
  static void draw_merged(CounterStream& s, const TapFrameLaw law[2], double fd_e[2], double ktc_V[2],
                          double read_V[2]) {
    const NormalZiggurat& normal = NormalZiggurat::tables();
    // Draw order: the two counts, then each tap's normal noise (one, or kTC and read apart).
    for (int k = 0; k < 2; ++k) fd_e[k] = law[k].count(s) - law[k].offset_e;  // the offset's deviation included
    for (int k = 0; k < 2; ++k) {
      if (law[k].may_saturate) {
        ktc_V[k] = normal(s) * law[k].ktc_fd_V;
        read_V[k] = normal(s) * law[k].read_V;
      } else {
        ktc_V[k] = 0;
        read_V[k] = normal(s) * law[k].sigma_V;  // the clip cannot act: kTC and read noise as one
      }
    }
  }
  // ... and the ADC input they make.
  static double input_V(const Readout& r, int tap, double fd_e, double offset_dev_e, double ktc_V, double read_V) {
    const double e = (fd_e + offset_dev_e) * r.volts_per_e[tap];
    double swing = (r.a_sf == 1.0 ? e : e / r.a_sf) + r.offset_V;  // x / 1 is x: no division
    swing += ktc_V;
    swing = std::min(swing, r.sat_V);
    return r.a_sf * swing + read_V;
  }
  double fd_e(int tap) const { return fd_e_[tap]; }

 private:
  double draw_poisson(const LockinSimOptions& o, double mean);
  void clear() {
    fd_e_[0] = fd_e_[1] = 0, pg_e_ = 0;
    ktc_V_[0] = ktc_V_[1] = read_V_[0] = read_V_[1] = 0;
    offset_dev_e_[0] = offset_dev_e_[1] = 0;
  }
  // The merged draws' stream at the frame's words; keyed anew only when seed, row or column change.
  void place_stream(std::uint64_t seed, std::uint64_t frame, std::uint32_t row, std::uint32_t column) {
    if (!stream_set_ || seed != stream_seed_ || row != stream_row_ || column != stream_column_)
      key_stream(seed, row, column);
    stream_.seek(frame << 32);
  }
  void key_stream(std::uint64_t seed, std::uint32_t row, std::uint32_t column) {
    stream_ = merged_stream(seed, row, column);
    stream_seed_ = seed, stream_row_ = row, stream_column_ = column, stream_set_ = true;
  }
  double fd_e_[2] = {0, 0};          // electrons on FD1 / FD2 (integer-valued with noise)
  double pg_e_ = 0;                  // mean electrons on the photogate in the open window
  double ktc_V_[2] = {0, 0};         // kTC reset noise on each FD (at the FD)
  double read_V_[2] = {0, 0};        // read noise of each tap's sample
  double offset_dev_e_[2] = {0, 0};  // offset charge of this frame minus its mean (its shot noise)
  pcg32 rng_;                        // the pixel's stream for this frame
  // The merged draws' stream, kept while seed, row and column stay (keying it costs two mixes).
  CounterStream stream_;
  std::uint64_t stream_seed_ = 0;
  std::uint32_t stream_row_ = 0, stream_column_ = 0;
  bool stream_set_ = false;
};

}  // namespace rangesim::systemc::lockin
