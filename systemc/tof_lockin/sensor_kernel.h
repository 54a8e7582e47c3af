#pragma once
// The tof-lockin sensor kernel: readout sequencer + pixel array + column ADCs, frames and ranges.
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
  // SNR of a + b of pixel (r, c) in range map m from its own tap values (golden/tof_lockin/validity.h).
  double snr(long long m, int r, int c) const;
  // Tap values a = V1 - V_cal (- ambient), b likewise, of range map m.
  void tap_values(long long m, int r, int c, double* a, double* b) const;
  int rows() const { return rows_; }
  int columns() const { return cols_; }
  const TofLockinConfig& config() const { return cfg_; }
  // Pixel (r, c) of the simulated window, for tracing its floating diffusions.
  const LockinPixelKernel& pixel(int r, int c) const { return pixels_[static_cast<std::size_t>(r) * cols_ + c]; }

 private:
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
  // Aggregation: each pixel's mean frame totals per tap, LED frame [1] and
  // ambient frame [0]; stimulus and gates are fixed, so computed once each.
  std::vector<double> frame_mean_e_[2];  // 2 per pixel (FD1, FD2)
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
