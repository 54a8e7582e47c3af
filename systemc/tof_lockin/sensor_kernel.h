#pragma once
// The tof-lockin sensor kernel: readout sequencer + pixel array + column ADCs, frames and ranges.
#include <limits>

#include "golden/tof_lockin/pulse_timing.h"
#include "golden/tof_lockin/validity.h"
#include "systemc/tof_lockin/frame_draw.h"
#include "systemc/tof_lockin/kernel_types.h"
#include "systemc/tof_lockin/column_adc_kernel.h"
#include "systemc/tof_lockin/lockin_gate_generator_kernel.h"
#include "systemc/tof_lockin/pixel_kernel.h"

namespace rangesim::systemc::lockin {

// ---------------------------------------------------------------- sensor:
// sequencer + array
struct LockinFrameRecord {
  long long frame = 0;                 // frame index
  bool led_on = true;                  // false: ambient frame
  long long cycles[kPhaseCount] = {};  // cycles per phase (gate clock for 1-3, readout clock for 4-5)
  double start_s = 0, end_s = 0;       // simulated time
};

class TofLockinSensorKernel {
 public:
  // sim_rows x sim_columns pixels (<= the configured array; the readout still
  // converts every row).
  TofLockinSensorKernel(const TofLockinConfig& cfg, const LockinSimOptions& opt, int sim_rows, int sim_columns,
                        std::vector<LockinPixelStimulus> stimulus, long long frames);
  // One event (or one cycle in tick mode). Returns false when all frames are
  // done.
  bool step();
  void run() {
    while (step()) {
    }
  }
  bool done() const { return frame_ >= frames_; }
  // Back to the state of a newly built kernel, with the noise streams keyed by `seed`: Monte Carlo
  // runs every trial of a point on one kernel, with no allocation, and keeps the frame means
  // (stimulus and gates are unchanged). Same seed, same bits as a new kernel.
  void restart(std::uint64_t seed);

  // Each pixel's mean frame totals per tap (2 per pixel: FD1, FD2; the offset charge apart) of an
  // aggregated LED (`on`) or ambient frame: every window over the frame's N_acc periods, the
  // pixel's fixed pattern, dark charge. Stimulus and gates are fixed, so a kernel computes them once.
  static std::vector<double> aggregated_frame_means(const TofLockinConfig& cfg, const LockinSimOptions& opt,
                                                    const LockinGateGeneratorKernel& gates,
                                                    const std::vector<LockinPixelStimulus>& stim, bool on);
  // Whether aggregated frames take the merged draws (config simulation.merged_draws, with noise).
  bool merged_draws() const { return merged_; }

  // State for ports / tracing.
  LockinPhase phase() const { return phase_; }
  const LockinGateGeneratorKernel& gates() const { return gates_; }
  long long frame() const { return frame_; }
  int readout_row() const { return row_; }
  bool led_on() const;
  double time_s() const;  // simulated time since the start
  long long gate_cycles() const { return gate_cycles_; }
  long long readout_cycles() const { return readout_cycles_; }
  long long events() const { return events_; }

  // Results.
  const std::vector<LockinFrameRecord>& frame_records() const { return records_; }
  // ADC code of tap k of pixel (r, c) in frame f.
  long long code(long long f, int r, int c, int k) const {
    return codes_[((static_cast<std::size_t>(f) * rows_ + r) * cols_ + c) * 2 + k];
  }
  double adc_input_V(long long f, int r, int c, int k) const {
    return inputs_[((static_cast<std::size_t>(f) * rows_ + r) * cols_ + c) * 2 + k];
  }
  long long range_maps() const;  // complete range maps among the frames run
  // Range of pixel (r, c) in range map m (eq. 2.25), NaN if not detected /
  // saturated.
  double range_m(long long m, int r, int c) const;
  // The rule behind range_m: one range map's codes (the LED frame's; the ambient frame's, used
  // with ambient subtraction) -> L = (c T0 / 2) b / (a + b), NaN when a code is clipped at full
  // scale, a + b <= 0 or a + b < detection_threshold_V.
  static double range_from_codes(const TofLockinConfig& cfg, const ColumnAdcKernel& adc, const long long led[2],
                                 const long long ambient[2]) {
    return range_from_codes(cfg, adc, golden::max_range_m(cfg.source), led, ambient);
  }
  // The same with K = c T0 / 2 computed once.
  static double range_from_codes(const TofLockinConfig& cfg, const ColumnAdcKernel& adc, double K_m,
                                 const long long led[2], const long long ambient[2]) {
    if (led[0] == adc.top_code() || led[1] == adc.top_code()) return kNoRange;  // saturated (clipped code)
    double v[2];
    for (int k = 0; k < 2; ++k) {
      v[k] = adc.value_V(led[k]) - cfg.readout.offset_calibration_V;
      if (cfg.readout.ambient_subtraction) v[k] -= adc.value_V(ambient[k]);
    }
    const double s = v[0] + v[1];
    if (!(s > 0.0) || s < cfg.readout.detection_threshold_V * (1.0 - 1e-9)) return kNoRange;
    return K_m * v[1] / s;
  }
  static constexpr double kNoRange = std::numeric_limits<double>::quiet_NaN();
  // SNR of a + b of pixel (r, c) in range map m from its own tap values (golden/tof_lockin/validity.h).
  double snr(long long m, int r, int c) const;
  // The rms noise of that range value from its own tap values (delta method), m.
  double range_noise_m(long long m, int r, int c) const;
  // A range (range_m finite) that passes the map's validity rule: SNR >= readout.min_snr and noise
  // <= readout.max_range_noise_fraction x c T0 / 2, golden's detectability on the pixel's own taps.
  bool range_valid(long long m, int r, int c) const;
  // Tap values a = V1 - V_cal (- ambient), b likewise, of range map m.
  void tap_values(long long m, int r, int c, double* a, double* b) const;
  int rows() const { return rows_; }
  int columns() const { return cols_; }
  const TofLockinConfig& config() const { return cfg_; }
  // Pixel (r, c) of the simulated window, for tracing its floating diffusions.
  const LockinPixelKernel& pixel(int r, int c) const { return pixels_[static_cast<std::size_t>(r) * cols_ + c]; }

 private:
  golden::MeasuredTaps measured_taps(long long m, int r, int c) const;
  void begin_frame();
  void end_accumulation_if_done();
  void convert_row(int r);

  TofLockinConfig cfg_;
  LockinSimOptions opt_;
  int rows_, cols_;
  std::vector<LockinPixelStimulus> stim_;
  long long frames_;
  LockinGateGeneratorKernel gates_;
  ColumnAdcKernel adc_;
  std::vector<LockinPixelKernel> pixels_;
  LockinPixelKernel::ResetNoise reset_noise_;
  LockinPixelKernel::Readout readout_;
  bool merged_;  // aggregated frames by their merged draws (frame_draw.h)
  // Aggregation: each pixel's mean frame totals per tap, LED frame [1] and
  // ambient frame [0]; stimulus and gates are fixed, so computed once each.
  std::vector<double> frame_mean_e_[2];  // 2 per pixel (FD1, FD2)
  FrameLaws laws_[2];                    // their merged draws' laws, likewise
  std::vector<long long> codes_;         // per frame, pixel, tap
  std::vector<double> inputs_;           // ADC inputs, same layout
  std::vector<LockinFrameRecord> records_;
  LockinPhase phase_ = LockinPhase::Idle;
  long long frame_ = 0;
  int row_ = 0;                   // row in readout
  long long in_phase_ = 0;        // cycles spent in the current readout phase of the row
  long long gate_cycles_ = 0;     // total gate-clock cycles
  long long readout_cycles_ = 0;  // total readout-clock cycles
  long long events_ = 0;          // steps taken
  bool started_ = false;
};

}  // namespace rangesim::systemc::lockin
