#include "systemc/ls_demodulation/demod_pixel_kernel.h"

#include <cmath>
#include <stdexcept>
#include <string>

#include "core/physics.h"
#include "systemc/random_stream.h"

namespace rangesim::systemc {

DemodWindowSchedule demod_window_schedule(const LsDemodulationConfig& cfg) {
  DemodWindowSchedule s;
  s.clock_Hz = cfg.readout.clock_Hz;
  const double pc = cfg.readout.clock_Hz / cfg.modulation.frequency_Hz;
  s.period_cycles = static_cast<int>(std::lround(pc));
  if (s.period_cycles < 2 || std::fabs(pc - s.period_cycles) > 1e-6)
    throw std::invalid_argument("readout.clock_Hz / modulation.frequency_Hz = " + std::to_string(pc) +
                                ": the clock-level model needs an integer number (>= 2) of clock cycles per correlation period");
  s.periods = cfg.correlator.cycles;
  const double win = cfg.pixel.integration_time_s * cfg.readout.clock_Hz;
  if (s.periods < 1 || std::fabs(win - s.window_cycles()) > 1.0 + 1e-9)
    throw std::invalid_argument("pixel.integration_time_s x readout.clock_Hz = " + std::to_string(win) +
                                " cycles differs from correlator.cycles x clock / f0 = " + std::to_string(s.window_cycles()));
  // Segment edges of a pixel that sees the beam (a zero beam has the same cuts).
  for (const auto& seg : golden::pixel_segments(cfg, 1e-12, 0.0)) {
    const double c = seg.duration_s * cfg.readout.clock_Hz;
    const int ci = static_cast<int>(std::lround(c));
    if (ci < 1 || std::fabs(c - ci) > 1e-6)
      throw std::invalid_argument("modulation.source_duty_cycle / correlator.reference_duty_cycle / modulation.reference_phase_rad: "
                                  "an MPY or beam edge falls between clock edges (" + std::to_string(c) + " cycles)");
    s.segment_cycles.push_back(ci);
    s.segment_branch.push_back(seg.branch);
  }
  return s;
}

DemodPixelKernel::DemodPixelKernel(const LsDemodulationConfig& cfg, const DemodWindowSchedule& sched)
    : cfg_(cfg), sched_(sched) {}

void DemodPixelKernel::reset(double beam_A, double background_A, pcg32& rng, const DemodNoiseSwitches& noise) {
  const auto period = golden::pixel_segments(cfg_, beam_A, background_A);
  if (period.size() != sched_.segment_cycles.size())
    throw std::logic_error("DemodPixelKernel: pixel segments differ from the window schedule");
  segments_.clear();
  for (int p = 0; p < sched_.periods; ++p) segments_.insert(segments_.end(), period.begin(), period.end());
  lpf_A_ = seg_start_lpf_A_ = golden::lpf_periodic_start_A(cfg_, period);
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
  shot_sd_V_.assign(segments_.size(), 0.0);
  if (!shot_) return;
  // Closed-form shot-noise variance per segment: golden front_end's forward pass for the noise
  // kernel k_j (segment mean of the log stage's small-signal gain), then its backward recursion.
  const auto& sup = cfg_.suppression;
  const auto& lg = cfg_.log_converter;
  const auto& co = cfg_.correlator;
  const double alpha = sup.mirror_gain, eps = sup.mirror_mismatch, tau = sup.lpf_time_constant_s;
  const double gain_V = co.transconductance_S * lg.gain * lg.slope_V;
  std::vector<double> k(segments_.size());
  double Iavg = lpf_A_, mean_A = 0, T = 0;
  for (std::size_t j = 0; j < segments_.size(); ++j) {
    const auto& s = segments_[j];
    const double I = s.photocurrent_A, L = s.duration_s;
    const auto li = golden::log_integral(lg.offset_current_A + alpha * eps * I, -alpha * (Iavg - I), tau, L,
                                         lg.leakage_current_A, lg.offset_current_A, alpha * eps * I);
    const double C = s.branch > 0 ? co.capacitance_plus_F : co.capacitance_minus_F;
    k[j] = s.branch * gain_V / C * li.inv_s_per_A / L;
    Iavg = I + (Iavg - I) * std::exp(-L / tau);
    if (j < period.size()) mean_A += I * L, T += L;
  }
  mean_A /= T;
  const double q = phys::kElementaryCharge_C;
  double G = 0;
  for (std::size_t jj = segments_.size(); jj-- > 0;) {
    const auto& s = segments_[jj];
    const double L = s.duration_s, e1 = -std::expm1(-L / tau), e2 = -std::expm1(-2 * L / tau);
    const double A = alpha * eps * k[jj], B = alpha * (k[jj] - G);
    shot_sd_V_[jj] = std::sqrt(std::max(0.0, q * s.photocurrent_A * (A * A * L + 2 * A * B * tau * e1 + B * B * 0.5 * tau * e2)));
    G = k[jj] * e1 + G * (1 - e1);
  }
  plus_V_ += n_past * std::sqrt(q * mean_A * alpha * alpha * G * G * 0.5 * tau);
}

int DemodPixelKernel::cycles_to_edge() const {
  if (window_done()) return 0;
  return sched_.segment_cycles[static_cast<std::size_t>(seg_index_) % sched_.segment_cycles.size()] - seg_cycle_;
}

void DemodPixelKernel::step(int cycles) {
  const int left = cycles_to_edge();
  if (cycles < 1 || cycles > left) throw std::logic_error("DemodPixelKernel::step: beyond the segment edge");
  const auto& s = segments_[static_cast<std::size_t>(seg_index_)];
  const auto& lg = cfg_.log_converter;
  const double alpha = cfg_.suppression.mirror_gain, eps = cfg_.suppression.mirror_mismatch;
  const double tau = cfg_.suppression.lpf_time_constant_s;
  const double I = s.photocurrent_A;
  // A whole segment uses golden's duration (bit-identical to golden); a piece, cycles / clock.
  const bool whole = seg_cycle_ == 0 && cycles == left;
  const double L = whole ? s.duration_s : cycles / sched_.clock_Hz;
  const auto li = golden::log_integral(lg.offset_current_A + alpha * eps * I, -alpha * (lpf_A_ - I), tau, L,
                                       lg.leakage_current_A, lg.offset_current_A, alpha * eps * I);
  const double gain_V = cfg_.correlator.transconductance_S * lg.gain * lg.slope_V;
  if (s.branch > 0)
    plus_V_ += gain_V / cfg_.correlator.capacitance_plus_F * li.ln_s;
  else
    minus_V_ += gain_V / cfg_.correlator.capacitance_minus_F * li.ln_s;
  lpf_A_ = I + (lpf_A_ - I) * std::exp(-L / tau);
  seg_cycle_ += cycles;
  if (cycles_to_edge() == 0) end_segment();
}

void DemodPixelKernel::end_segment() {
  const auto& s = segments_[static_cast<std::size_t>(seg_index_)];
  if (shot_) {
    const double n = standard_normal(*rng_) * shot_sd_V_[static_cast<std::size_t>(seg_index_)];
    if (s.branch > 0) plus_V_ += n; else minus_V_ -= n;  // adds n to D either way
  }
  ++seg_index_;
  seg_cycle_ = 0;
}

}  // namespace rangesim::systemc
