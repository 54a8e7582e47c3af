#include "systemc/tof_lockin/sensor_kernel.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <fmt/format.h>
#include <limits>
#include <random>

#include "core/physics.h"
#include "core/user_error.h"
#include "golden/tof_lockin/validity.h"
#include "golden/tof_lockin/pulse_timing.h"
#include "golden/tof_lockin/tap_charge.h"
#include "systemc/common/poisson_sampler.h"
#include "systemc/common/random_stream.h"

namespace rangesim::systemc::lockin {

// ---------------------------------------------------------------- sensor

TofLockinSensorKernel::TofLockinSensorKernel(const TofLockinConfig& cfg, const LockinSimOptions& opt, int sim_rows,
                                             int sim_columns, std::vector<LockinPixelStimulus> stimulus,
                                             long long frames)
    : cfg_(cfg),
      opt_(opt),
      rows_(sim_rows),
      cols_(sim_columns),
      stim_(std::move(stimulus)),
      frames_(frames),
      gates_(cfg),
      adc_(cfg),
      reset_noise_(LockinPixelKernel::ResetNoise::of(cfg)),
      readout_(LockinPixelKernel::Readout::of(cfg)),
      merged_(cfg.simulation.merged_draws && opt.noise && opt.event_skipping && opt.aggregate) {
  assert(rows_ >= 0 && rows_ <= cfg.pixel.rows && cols_ >= 0 && cols_ <= cfg.pixel.columns);
  assert(stim_.size() == static_cast<std::size_t>(rows_) * cols_);
  assert(frames_ >= 0);
  pixels_.resize(stim_.size());
  codes_.assign(static_cast<std::size_t>(frames_) * stim_.size() * 2, 0);
  inputs_.assign(codes_.size(), 0.0);
}

void TofLockinSensorKernel::restart(std::uint64_t seed) {
  opt_.seed = seed;
  records_.clear();
  phase_ = LockinPhase::Idle;
  frame_ = 0, row_ = 0, in_phase_ = 0;
  gate_cycles_ = 0, readout_cycles_ = 0, events_ = 0;
  started_ = false;
  // codes_ and inputs_ are rewritten frame by frame before they are read; the pixels and the
  // gates are reset at each frame's start.
}

bool TofLockinSensorKernel::led_on() const { return !(cfg_.readout.ambient_subtraction && frame_ % 2 == 1); }

double TofLockinSensorKernel::time_s() const {
  return static_cast<double>(gate_cycles_) / cfg_.gates.clock_Hz +
         static_cast<double>(readout_cycles_) / cfg_.readout.clock_Hz;
}

void TofLockinSensorKernel::begin_frame() {
  LockinFrameRecord rec;
  rec.frame = frame_;
  rec.led_on = led_on();
  rec.start_s = time_s();
  records_.push_back(rec);
  for (int r = 0; r < rows_; ++r)
    for (int c = 0; c < cols_; ++c)
      pixels_[static_cast<std::size_t>(r) * cols_ + c].reset(reset_noise_, opt_, static_cast<std::uint64_t>(frame_),
                                                             static_cast<std::uint32_t>(r),
                                                             static_cast<std::uint32_t>(c), merged_);
  gates_.start();
  phase_ = gates_.phase();
  row_ = 0, in_phase_ = 0;
}

void TofLockinSensorKernel::convert_row(int r) {
  if (r >= rows_) return;  // rows outside the simulated window are converted without pixels
  for (int c = 0; c < cols_; ++c) {
    const std::size_t p = static_cast<std::size_t>(r) * cols_ + c;
    for (int k = 0; k < 2; ++k) {
      const std::size_t i = (static_cast<std::size_t>(frame_) * stim_.size() + p) * 2 + k;
      inputs_[i] = pixels_[p].adc_input_V(readout_, k);
      codes_[i] = adc_.code(inputs_[i]);
    }
  }
}

std::vector<double> TofLockinSensorKernel::aggregated_frame_means(const TofLockinConfig& cfg,
                                                                  const LockinSimOptions& opt,
                                                                  const LockinGateGeneratorKernel& gates,
                                                                  const std::vector<LockinPixelStimulus>& stim,
                                                                  bool on) {
  const double fg = cfg.gates.clock_Hz;
  const long long n = gates.accumulations();
  const double leak = (1.0 - cfg.pixel.drain_efficiency) / 2.0;
  const double period_s = static_cast<double>(gates.period_cycles()) / fg;
  const double dark_per_A = static_cast<double>(n) * period_s / phys::kElementaryCharge_C;
  double t[3][2];
  for (int w = 0; w < 3; ++w)
    t[w][0] = static_cast<double>(gates.window_open(w)) / fg, t[w][1] = static_cast<double>(gates.window_close(w)) / fg;
  std::vector<double> mean(2 * stim.size());
  for (std::size_t p = 0; p < stim.size(); ++p) {
    double g[3];
    for (int w = 0; w < 3; ++w)
      g[w] = LockinPixelKernel::frame_generated_e(cfg, stim[p], on, t[w][0], t[w][1], n, opt.time_step_s);
    // The pixel's fixed pattern: each tap's gain on its photo charge, its own dark current.
    const LockinPixelStimulus& sp = stim[p];
    for (int k = 0; k < 2; ++k)
      mean[2 * p + k] =
          sp.tap_gain[k] * (g[k] + leak * g[2]) + (cfg.noise.dark_current_A + sp.dark_extra_A[k]) * dark_per_A;
  }
  return mean;
}

bool TofLockinSensorKernel::step() {
  if (done()) return false;
  if (phase_ == LockinPhase::Idle) begin_frame();
  ++events_;
  LockinFrameRecord& rec = records_.back();
  const double fg = cfg_.gates.clock_Hz;
  if (phase_ == LockinPhase::Phase1 || phase_ == LockinPhase::Phase2 || phase_ == LockinPhase::Phase3) {
    const bool on = led_on();
    if (opt_.event_skipping && opt_.aggregate && gates_.accumulation() == 0 && gates_.cycle_in_period() == 0) {
      // A frame's N_acc periods in one event: the total mean of every window
      // over the frame, Poisson of the total (a sum of independent Poisson
      // counts). Periods differ only by the tail of the previous pulse.
      const long long n = gates_.accumulations();
      const int kind = on ? 1 : 0;
      if (frame_mean_e_[kind].empty()) {
        frame_mean_e_[kind] = aggregated_frame_means(cfg_, opt_, gates_, stim_, on);
        if (merged_) {
          // Frames of this kind over the run: LED and ambient frames alternate with ambient subtraction.
          const long long led = cfg_.readout.ambient_subtraction ? (frames_ + 1) / 2 : frames_;
          laws_[kind].build(cfg_, frame_mean_e_[kind], reset_noise_.offset_e, opt_.poisson_tables,
                            on ? led : frames_ - led);
        }
      }
      if (merged_) {
        for (std::size_t p = 0; p < pixels_.size(); ++p) pixels_[p].aggregate_merged(laws_[kind].pixel(p));
      } else {
        const std::vector<double>& mean = frame_mean_e_[kind];
        for (std::size_t p = 0; p < pixels_.size(); ++p) pixels_[p].aggregate(opt_, &mean[2 * p]);
      }
      rec.cycles[0] += n * gates_.t0_cycles();
      rec.cycles[1] += n * gates_.t0_cycles();
      rec.cycles[2] += n * (gates_.period_cycles() - 2 * gates_.t0_cycles());
      gate_cycles_ += gates_.finish_all();
    } else {
      const int w = static_cast<int>(phase_) - 1;
      const long long n = opt_.event_skipping ? gates_.cycles_to_edge() : 1;
      const long long pos = gates_.cycle_in_period() + n;
      const long long period = gates_.accumulation();
      gates_.advance(n);
      gate_cycles_ += n;
      rec.cycles[w] += n;
      const bool closed = pos == gates_.window_close(w);
      const double t_open = static_cast<double>(gates_.window_open(w)) / fg, t_now = static_cast<double>(pos) / fg;
      const double period_s = static_cast<double>(gates_.period_cycles()) / fg;
      // PHASE3 of zero length (duty 0.5): the drain edge coincides with the TX2
      // closing edge.
      const bool empty_drain = closed && w == 1 && gates_.period_cycles() == 2 * gates_.t0_cycles();
      for (std::size_t p = 0; p < pixels_.size(); ++p) {
        pixels_[p].collect(cfg_, opt_, stim_[p], on, t_open, t_now, period);
        if (closed) pixels_[p].transfer(cfg_, opt_, stim_[p], w, period_s);
        if (empty_drain) pixels_[p].transfer(cfg_, opt_, stim_[p], 2, period_s);
      }
    }
    if (gates_.done()) {
      phase_ = LockinPhase::AdcConversion, row_ = 0, in_phase_ = 0;
    } else {
      phase_ = gates_.phase();
    }
  } else if (phase_ == LockinPhase::AdcConversion) {
    const long long total = adc_.conversion_cycles();
    const long long n = opt_.event_skipping ? total - in_phase_ : 1;
    in_phase_ += n, readout_cycles_ += n, rec.cycles[3] += n;
    if (in_phase_ == total) convert_row(row_), phase_ = LockinPhase::Output, in_phase_ = 0;
  } else if (phase_ == LockinPhase::Output) {
    const long long total = cfg_.readout.output_cycles_per_row;
    const long long n = opt_.event_skipping ? total - in_phase_ : 1;
    in_phase_ += n, readout_cycles_ += n, rec.cycles[4] += n;
    if (in_phase_ == total) {
      in_phase_ = 0;
      if (++row_ == cfg_.pixel.rows) {
        rec.end_s = time_s();
        ++frame_;
        phase_ = LockinPhase::Idle;
      } else {
        phase_ = LockinPhase::AdcConversion;
      }
    }
  }
  return !done();
}

long long TofLockinSensorKernel::range_maps() const {
  const long long done_frames = static_cast<long long>(frame_);
  return cfg_.readout.ambient_subtraction ? done_frames / 2 : done_frames;
}

void TofLockinSensorKernel::tap_values(long long m, int r, int c, double* a, double* b) const {
  const long long f = cfg_.readout.ambient_subtraction ? 2 * m : m;
  double v[2];
  for (int k = 0; k < 2; ++k) {
    v[k] = adc_.value_V(code(f, r, c, k)) - cfg_.readout.offset_calibration_V;
    if (cfg_.readout.ambient_subtraction) v[k] -= adc_.value_V(code(f + 1, r, c, k));
  }
  *a = v[0], *b = v[1];
}

golden::MeasuredTaps TofLockinSensorKernel::measured_taps(long long m, int r, int c) const {
  const long long f = cfg_.readout.ambient_subtraction ? 2 * m : m;
  golden::MeasuredTaps t;
  for (int k = 0; k < 2; ++k) {
    t.led_V[k] = adc_.value_V(code(f, r, c, k));
    if (cfg_.readout.ambient_subtraction) t.ambient_V[k] = adc_.value_V(code(f + 1, r, c, k));
  }
  return t;
}

double TofLockinSensorKernel::snr(long long m, int r, int c) const {
  return golden::measured_snr(cfg_, measured_taps(m, r, c));
}

double TofLockinSensorKernel::range_noise_m(long long m, int r, int c) const {
  return golden::measured_range_noise_m(cfg_, measured_taps(m, r, c));
}

bool TofLockinSensorKernel::range_valid(long long m, int r, int c) const {
  return std::isfinite(range_m(m, r, c)) && golden::measured_range_valid(cfg_, measured_taps(m, r, c));
}

double TofLockinSensorKernel::range_m(long long m, int r, int c) const {
  const long long f = cfg_.readout.ambient_subtraction ? 2 * m : m;
  const long long led[2] = {code(f, r, c, 0), code(f, r, c, 1)};
  long long ambient[2] = {0, 0};
  if (cfg_.readout.ambient_subtraction) ambient[0] = code(f + 1, r, c, 0), ambient[1] = code(f + 1, r, c, 1);
  return range_from_codes(cfg_, adc_, led, ambient);
}

}  // namespace rangesim::systemc::lockin
