// Monte Carlo trials of tof-lockin on the kernels (one pixel): each trial the sensor kernel's
// frames, or (simulation.direct_trials) the same pixel, ADC and range rule without the sequencer.
#include <cmath>
#include <optional>

#include "systemc/tof_lockin/montecarlo.h"
#include "golden/tof_lockin/pulse_timing.h"
#include "systemc/tof_lockin/code_law.h"
#include "systemc/tof_lockin/nonideal_stimulus.h"
#include "systemc/tof_lockin/sensor_kernel.h"

namespace rangesim::mc {

namespace {

namespace lk = systemc::lockin;

class Runner : public McPointRunner {
 public:
  // A point's alias tables cost about as much as this many trials drawn by PTRS.
  static constexpr long long kTablesFromTrial = 1024;

  Runner(const TofLockinConfig& cfg, bool aggregate, long long code_tables_from, double signal_A, double background_A,
         std::uint64_t key)
      : cfg_(cfg),
        aggregate_(aggregate),
        code_tables_from_(code_tables_from),
        key_(key),
        stim_{signal_A, background_A, golden::round_trip_delay_s(cfg.eval.distance_m)},
        gates_(cfg),
        adc_(cfg),
        noise_(lk::LockinPixelKernel::ResetNoise::of(cfg)),
        readout_(lk::LockinPixelKernel::Readout::of(cfg)),
        range_m_(golden::max_range_m(cfg.source)) {
    cfg_.pixel.rows = 1;
    // Every trial is a pixel of another chip when the fixed pattern is on (its stimulus keyed by
    // the trial): then the laws change every trial and alias tables would not pay.
    fixed_pattern_ = cfg_.nonideal.fixed_pattern.any();
    opt_.event_skipping = true, opt_.aggregate = aggregate_;
    opt_.poisson_tables = lk::PoissonTables::Never;
    const long long maps = std::max<long long>(1, cfg_.eval.frames_averaged);
    frames_ = maps * (cfg_.readout.ambient_subtraction ? 2 : 1);
    // The direct path needs the aggregated frame (one draw event per frame); noise is always on here.
    direct_ = cfg_.simulation.direct_trials && aggregate_;
    merged_ = cfg_.simulation.merged_draws && aggregate_;
    // The codes' own laws (code_law.h) need the merged draws' laws without the V_sat clip.
    codes_ = cfg_.simulation.code_tables && direct_ && merged_ && !fixed_pattern_;
  }

  McTrial trial(long long t) override {
    // The trial's streams: (trial key, frame, row 0, column 0) in either path.
    const std::uint64_t seed = trial_key(key_, static_cast<std::uint64_t>(t));
    // Without the fixed pattern every trial draws the same laws: from kTablesFromTrial on (the
    // trials before pay for the alias tables, frame_draw.h) their counts come from tables. The
    // switch is a function of the trial index, taken by both paths alike.
    const bool tables = !fixed_pattern_ && t >= kTablesFromTrial;
    if (tables != (opt_.poisson_tables == lk::PoissonTables::Always)) {
      opt_.poisson_tables = tables ? lk::PoissonTables::Always : lk::PoissonTables::Never;
      stim_now_.clear();  // laws and kernel made anew below
    }
    // One pixel of a uniform plane: the point spread changes nothing there, the second return does.
    if (fixed_pattern_ || stim_now_.empty()) {
      stim_now_ = {stim_};
      lk::add_multipath(cfg_, stim_now_);
      lk::apply_fixed_pattern(cfg_, seed, stim_now_, 1, 1);
      if (direct_) set_frame_laws();
      kernel_.reset();
    }
    if (codes_ && t >= code_tables_from_ && !code_laws_set_) set_code_laws();
    if (code_laws_ready_ && t >= code_tables_from_) return code_trial(seed);
    return direct_ ? direct_trial(seed) : kernel_trial(seed);
  }

  // Once the code laws are drawn (every trial from code_tables_from_ on, ready after the first of
  // them through trial()), trial() changes no state the codes depend on: the code trials run here
  // in one inlined loop, the same values.
  void trials(long long t0, long long n, McTrial* out) override {
    long long i = 0;
    for (; i < n && !(code_laws_ready_ && t0 + i >= code_tables_from_); ++i) out[i] = trial(t0 + i);
    for (; i < n; ++i) out[i] = code_trial(trial_key(key_, static_cast<std::uint64_t>(t0 + i)));
  }

 private:
  // The frame means and merged laws of the pixel, as the sensor kernel computes them.
  void set_frame_laws() {
    for (int kind = 0; kind < 2; ++kind) {
      means_[kind] = lk::TofLockinSensorKernel::aggregated_frame_means(cfg_, opt_, gates_, stim_now_, kind == 1);
      if (merged_) laws_[kind].build(cfg_, means_[kind], noise_.offset_e, opt_.poisson_tables, frames_);
    }
  }

  // Each tap's code law of the LED and the ambient frame (code_law.h), where none can saturate.
  void set_code_laws() {
    code_laws_set_ = true;
    for (int kind = 0; kind < 2; ++kind)
      for (int k = 0; k < 2; ++k)
        if (laws_[kind].pixel(0)[k].may_saturate) return;  // drawn as the kernel draws them
    for (int kind = 0; kind < 2; ++kind)
      for (int k = 0; k < 2; ++k) {
        const lk::TapFrameLaw& l = laws_[kind].pixel(0)[k];
        const lk::TapFrameLaw& l0 = laws_[kind].pixel(0)[0];
        // The ambient frame's taps usually share their law (same charge, same FD): one table.
        const bool same = k == 1 && l.count_mean_e == l0.count_mean_e && l.offset_e == l0.offset_e &&
                          l.sigma_V == l0.sigma_V && readout_.volts_per_e[1] == readout_.volts_per_e[0];
        code_laws_[kind][k] = same ? code_laws_[kind][0] : lk::tap_code_table(l, readout_, adc_, k);
      }
    code_laws_ready_ = true;
  }

  // The codes drawn from their own laws: one word per code, from the trial's pixel stream.
  McTrial code_trial(std::uint64_t seed) {
    const bool ambient = cfg_.readout.ambient_subtraction;
    const long long per_map = ambient ? 2 : 1;
    lk::CounterStream stream = lk::LockinPixelKernel::merged_stream(seed, 0, 0);
    double sum = 0;
    for (long long f = 0; f < frames_; f += per_map) {
      long long codes[2][2] = {{0, 0}, {0, 0}};  // [LED, ambient][tap]
      for (long long j = 0; j < per_map; ++j) {
        stream.seek(static_cast<std::uint64_t>(f + j) << 32);
        const auto& law = code_laws_[j == 0 ? 1 : 0];
        codes[j][0] = law[0](stream), codes[j][1] = law[1](stream);
      }
      const double L = lk::TofLockinSensorKernel::range_from_codes(cfg_, adc_, range_m_, codes[0], codes[1]);
      if (!std::isfinite(L)) return {};  // a map without a range: the averaged value is missing
      sum += L;
    }
    return averaged(sum, frames_ / per_map);
  }

  // The sensor kernel's frames: one kernel for all the point's trials, restarted with the trial's
  // streams (the same bits as a kernel built per trial), rebuilt when the chip changes.
  McTrial kernel_trial(std::uint64_t seed) {
    lk::LockinSimOptions o = opt_;
    o.seed = seed;
    if (!kernel_)
      kernel_.emplace(cfg_, o, 1, 1, stim_now_, frames_);
    else
      kernel_->restart(seed);
    lk::TofLockinSensorKernel& k = *kernel_;
    k.run();  // bounded: the frames' schedule has a fixed number of events
    double sum = 0;
    for (long long m = 0; m < k.range_maps(); ++m) {
      const double L = k.range_m(m, 0, 0);
      if (!std::isfinite(L)) return {};  // a map without a range: the averaged value is missing
      sum += L;
    }
    return averaged(sum, k.range_maps());
  }

  // The same frames without the sequencer: the pixel's reset and aggregated draw, the column ADC
  // and the kernel's range rule, frame by frame (the schedule's cycles change no draw).
  McTrial direct_trial(std::uint64_t seed) {
    const bool ambient = cfg_.readout.ambient_subtraction;
    const long long per_map = ambient ? 2 : 1;
    lk::CounterStream stream;
    if (merged_) stream = lk::LockinPixelKernel::merged_stream(seed, 0, 0);
    opt_.seed = seed;
    double sum = 0;
    for (long long f = 0; f < frames_; f += per_map) {
      long long codes[2][2] = {{0, 0}, {0, 0}};  // [LED, ambient][tap]
      for (long long j = 0; j < per_map; ++j) {
        const int kind = j == 0 ? 1 : 0;  // the LED frame first
        const auto frame = static_cast<std::uint64_t>(f + j);
        if (merged_) {  // the pixel's reset and aggregate_merged, without its state
          double fd[2], ktc[2], read[2];
          stream.seek(frame << 32);
          lk::LockinPixelKernel::draw_merged(stream, laws_[kind].pixel(0), fd, ktc, read);
          for (int k = 0; k < 2; ++k)
            codes[j][k] = adc_.code(lk::LockinPixelKernel::input_V(readout_, k, fd[k], 0.0, ktc[k], read[k]));
        } else {
          pixel_.reset(noise_, opt_, frame, 0, 0);
          pixel_.aggregate(opt_, means_[kind].data());
          for (int k = 0; k < 2; ++k) codes[j][k] = adc_.code(pixel_.adc_input_V(readout_, k));
        }
      }
      const double L = lk::TofLockinSensorKernel::range_from_codes(cfg_, adc_, range_m_, codes[0], codes[1]);
      if (!std::isfinite(L)) return {};  // a map without a range: the averaged value is missing
      sum += L;
    }
    return averaged(sum, frames_ / per_map);
  }

  // A trial whose every map gave a range: the error of their average.
  McTrial averaged(double sum, long long maps) const {
    McTrial t;
    t.detected = true;
    t.error = sum / static_cast<double>(maps) - cfg_.eval.distance_m;
    return t;
  }

  TofLockinConfig cfg_;
  bool aggregate_;
  long long code_tables_from_;
  bool fixed_pattern_ = false, direct_ = false, merged_ = false, codes_ = false;
  bool code_laws_set_ = false, code_laws_ready_ = false;
  lk::AliasTable code_laws_[2][2];  // [ambient, LED][tap]
  std::uint64_t key_;
  lk::LockinPixelStimulus stim_;
  lk::LockinSimOptions opt_;
  long long frames_ = 0;
  std::vector<lk::LockinPixelStimulus> stim_now_;    // stim_ with the trial's chip
  std::optional<lk::TofLockinSensorKernel> kernel_;  // built at the first trial
  // Direct trials.
  lk::LockinGateGeneratorKernel gates_;
  lk::ColumnAdcKernel adc_;
  lk::LockinPixelKernel::ResetNoise noise_;
  lk::LockinPixelKernel::Readout readout_;
  double range_m_;  // c T0 / 2
  lk::LockinPixelKernel pixel_;
  std::vector<double> means_[2];  // [ambient, LED] frame means per tap
  lk::FrameLaws laws_[2];
};

}  // namespace

TofLockinMc::TofLockinMc(TofLockinConfig cfg, bool aggregate, long long code_tables_from_trial)
    : cfg_(std::move(cfg)), aggregate_(aggregate), code_tables_from_(code_tables_from_trial) {}

std::unique_ptr<McPointRunner> TofLockinMc::point(double signal_A, double background_A, std::uint64_t key) const {
  return std::make_unique<Runner>(cfg_, aggregate_, code_tables_from_, signal_A, background_A, key);
}

std::unique_ptr<McModel> make_tof_lockin_mc(const ParamSet& params) {
  return std::make_unique<TofLockinMc>(tof_lockin_from_params(params));
}

}  // namespace rangesim::mc
