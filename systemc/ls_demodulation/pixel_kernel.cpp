#include "systemc/ls_demodulation/pixel_kernel.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "core/physics.h"
#include "systemc/common/random_stream.h"

namespace rangesim::systemc {

DemodWindowSchedule demod_window_schedule(const LsDemodulationConfig& cfg) {
  DemodWindowSchedule s;
  s.clock_Hz = cfg.readout.clock_Hz;
  const double pc = cfg.readout.clock_Hz / cfg.modulation.frequency_Hz;
  s.period_cycles = static_cast<int>(std::lround(pc));
  if (s.period_cycles < 2 || std::fabs(pc - s.period_cycles) > 1e-6)
    throw std::invalid_argument(
        "readout.clock_Hz / modulation.frequency_Hz = " + std::to_string(pc) +
        ": the clock-level model needs an integer number (>= 2) of clock cycles per correlation period");
  s.periods = cfg.correlator.cycles;
  const double win = cfg.pixel.integration_time_s * cfg.readout.clock_Hz;
  if (s.periods < 1 || std::fabs(win - s.window_cycles()) > 1.0 + 1e-9)
    throw std::invalid_argument(
        "pixel.integration_time_s x readout.clock_Hz = " + std::to_string(win) +
        " cycles differs from correlator.cycles x clock / f0 = " + std::to_string(s.window_cycles()));
  // Segment edges of a pixel that sees the beam (a zero beam has the same cuts).
  for (const auto& seg : golden::pixel_segments(cfg, 1e-12, 0.0)) {
    const double c = seg.duration_s * cfg.readout.clock_Hz;
    const int ci = static_cast<int>(std::lround(c));
    if (ci < 1 || std::fabs(c - ci) > 1e-6)
      throw std::invalid_argument(
          "modulation.source_duty_cycle / correlator.reference_duty_cycle / modulation.reference_phase_rad: "
          "an MPY or beam edge falls between clock edges (" +
          std::to_string(c) + " cycles)");
    s.segment_cycles.push_back(ci);
    s.segment_branch.push_back(seg.branch);
  }
  return s;
}

DemodPixelKernel::DemodPixelKernel(const LsDemodulationConfig& cfg, const DemodWindowSchedule& sched)
    : cfg_(cfg), sched_(sched) {}

void DemodPixelKernel::reset(double beam_A, double background_A, pcg32& rng, const DemodNoiseSwitches& noise,
                             bool aggregate) {
  period_ = golden::pixel_segments(cfg_, beam_A, background_A);
  if (period_.size() != sched_.segment_cycles.size())
    throw std::logic_error("DemodPixelKernel: pixel segments differ from the window schedule");
  dc0_A_ = period_.front().dc_A;
  lpf_offset_A_ = golden::lpf_periodic_offset_A(cfg_, period_);
  aggregate_ = aggregate;
  period_index_ = 0;
  seg_index_ = 0;
  seg_cycle_ = 0;
  rng_ = &rng;
  shot_ = noise.shot;
  const double kT = phys::kBoltzmann_J_per_K * cfg_.noise.temperature_K;
  const double n_ktc_p = standard_normal(rng), n_ktc_m = standard_normal(rng);
  const double n_fpn = standard_normal(rng), n_past = standard_normal(rng);
  plus_V_ = noise.ktc ? n_ktc_p * std::sqrt(kT / cfg_.correlator.capacitance_plus_F) : 0.0;
  minus_V_ = noise.ktc ? n_ktc_m * std::sqrt(kT / cfg_.correlator.capacitance_minus_F) : 0.0;
  if (noise.fixed_pattern) plus_V_ += n_fpn * cfg_.noise.fixed_pattern_rms_V;
  noise_.reset();
  if (aggregate_) {
    // The whole window in closed form now; step() adds it at the window's end.
    window_ = golden::correlate_periodic(cfg_, period_, sched_.periods);
    if (shot_) plus_V_ += n_past * std::sqrt(window_.shot_var_past_V2);
    return;
  }
  if (!shot_) return;
  // Closed-form shot-noise variance per segment: golden front_end's noise kernel k_j of one period
  // (periodic steady state: the same in every period) and its backward recursion, G at each
  // period's end by binary powering (begin_period), so memory stays O(S + log N).
  noise_.emplace(cfg_, period_, golden::period_noise_kernel(cfg_, period_, lpf_offset_A_), sched_.periods);
  double mean_A = 0, T = 0;
  for (const auto& s : period_) mean_A += s.photocurrent_A * s.duration_s, T += s.duration_s;
  plus_V_ += n_past * std::sqrt(golden::past_shot_var_V2(cfg_, mean_A / T, noise_->g_end(sched_.periods)));
  begin_period();
}

void DemodPixelKernel::begin_period() {
  if (!noise_) return;
  double G = noise_->g_end(sched_.periods - 1 - period_index_);
  shot_sd_V_.resize(period_.size());
  for (std::size_t jj = period_.size(); jj-- > 0;)
    shot_sd_V_[jj] = std::sqrt(std::max(0.0, noise_->segment_var_V2(jj, G)));
}

long long DemodPixelKernel::cycles_to_edge() const {
  if (window_done()) return 0;
  if (aggregate_) return sched_.window_cycles();
  return sched_.segment_cycles[seg_index_] - seg_cycle_;
}

void DemodPixelKernel::step(long long cycles) {
  const long long left = cycles_to_edge();
  if (cycles < 1 || cycles > left) throw std::logic_error("DemodPixelKernel::step: beyond the segment edge");
  if (aggregate_) {
    if (cycles != left) throw std::logic_error("DemodPixelKernel::step: an aggregated window is one step");
    plus_V_ += window_.plus_V;
    minus_V_ += window_.minus_V;
    if (shot_) {  // C1 first, then C2 (independent sums of independent Gaussians)
      plus_V_ += standard_normal(*rng_) * std::sqrt(window_.shot_var_plus_V2);
      minus_V_ -= standard_normal(*rng_) * std::sqrt(window_.shot_var_minus_V2);
    }
    lpf_offset_A_ = window_.lpf_end_A - dc0_A_;
    period_index_ = sched_.periods;
    return;
  }
  const auto& s = period_[seg_index_];
  // A whole segment uses golden's duration (bit-identical to golden); a piece, cycles / clock.
  const bool whole = seg_cycle_ == 0 && cycles == left;
  const double L = whole ? s.duration_s : static_cast<double>(cycles) / sched_.clock_Hz;
  const auto& lg = cfg_.log_converter;
  const double alpha = cfg_.suppression.mirror_gain, eps = cfg_.suppression.mirror_mismatch;
  const double tau = cfg_.suppression.lpf_time_constant_s;
  const double I = s.photocurrent_A;
  const auto li =
      golden::log_integral(lg.offset_current_A + alpha * eps * I, -alpha * golden::lpf_lag_A(lpf_offset_A_, s, dc0_A_),
                           tau, L, lg.leakage_current_A, lg.offset_current_A, alpha * eps * I);
  const double gain_V = cfg_.correlator.transconductance_S * lg.gain * lg.slope_V;
  if (s.branch > 0)
    plus_V_ += gain_V / cfg_.correlator.capacitance_plus_F * li.ln_s;
  else
    minus_V_ += gain_V / cfg_.correlator.capacitance_minus_F * li.ln_s;
  lpf_offset_A_ = golden::lpf_offset_after_A(cfg_, lpf_offset_A_, s, dc0_A_, L);
  seg_cycle_ += cycles;
  if (cycles_to_edge() == 0) end_segment();
}

void DemodPixelKernel::end_segment() {
  const auto& s = period_[seg_index_];
  if (shot_) {
    const double n = standard_normal(*rng_) * shot_sd_V_[seg_index_];
    if (s.branch > 0)
      plus_V_ += n;
    else
      minus_V_ -= n;  // adds n to D either way
  }
  seg_cycle_ = 0;
  if (++seg_index_ < period_.size()) return;
  seg_index_ = 0;
  if (++period_index_ < sched_.periods) begin_period();
}

}  // namespace rangesim::systemc
