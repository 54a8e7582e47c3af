#include "systemc/tof_lockin/pixel_kernel.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <fmt/format.h>
#include <limits>
#include <random>

#include "core/physics.h"
#include "core/user_error.h"
#include "golden/tof_lockin/pulse_timing.h"
#include "golden/tof_lockin/tap_charge.h"
#include "systemc/common/poisson_sampler.h"
#include "systemc/common/random_stream.h"

namespace rangesim::systemc::lockin {

// ---------------------------------------------------------------- photogate
// pixel

double LockinPixelKernel::generated_e(const TofLockinConfig& cfg, const LockinPixelStimulus& s, bool led_on, double t_a,
                                      double t_b, long long period, double time_step_s) {
  const double q = phys::kElementaryCharge_C;
  const double T0 = cfg.source.pulse_width_s;
  const double Trep = golden::repetition_period_s(cfg.source);
  double e = s.background_A * (t_b - t_a);
  const auto add = [&](double signal_A, double delay_s) {
    if (!led_on || signal_A == 0.0) return;
    const double eta = cfg.pixel.charge_separation;
    const double light = golden::window_light_in_period_s(cfg.source, delay_s, t_a, t_b, period, time_step_s);
    e += eta * signal_A * light + (1.0 - eta) * signal_A * T0 / Trep * (t_b - t_a);
  };
  add(s.signal_A, s.delay_s);
  for (const LockinEcho& echo : s.echoes) add(echo.signal_A, echo.delay_s);
  return e / q;
}

double LockinPixelKernel::frame_generated_e(const TofLockinConfig& cfg, const LockinPixelStimulus& s, bool led_on,
                                            double t_a, double t_b, long long n, double time_step_s) {
  const double q = phys::kElementaryCharge_C;
  const double T0 = cfg.source.pulse_width_s;
  const double Trep = golden::repetition_period_s(cfg.source);
  const double nd = static_cast<double>(n);
  double e = s.background_A * nd * (t_b - t_a);
  const auto add = [&](double signal_A, double delay_s) {
    if (!led_on || signal_A == 0.0) return;
    const double eta = cfg.pixel.charge_separation;
    const double light = golden::window_light_in_frame_s(cfg.source, delay_s, t_a, t_b, n, time_step_s);
    e += eta * signal_A * light + (1.0 - eta) * signal_A * T0 / Trep * nd * (t_b - t_a);
  };
  add(s.signal_A, s.delay_s);
  for (const LockinEcho& echo : s.echoes) add(echo.signal_A, echo.delay_s);
  return e / q;
}

LockinPixelKernel::Readout LockinPixelKernel::Readout::of(const TofLockinConfig& cfg) {
  Readout r;
  r.a_sf = cfg.pixel.source_follower_gain;
  for (int k = 0; k < 2; ++k) r.volts_per_e[k] = golden::volts_per_electron(cfg, k);
  r.offset_V = cfg.pixel.offset_voltage_V;
  r.sat_V = cfg.pixel.saturation_voltage_V;
  return r;
}

LockinPixelKernel::ResetNoise LockinPixelKernel::ResetNoise::of(const TofLockinConfig& cfg) {
  ResetNoise n;
  for (int k = 0; k < 2; ++k) n.ktc_fd_V[k] = golden::ktc_noise_V(cfg, k) / cfg.pixel.source_follower_gain;
  n.read_V = cfg.noise.read_noise_V;
  // The offset charge C V_offset / q of each FD, Poisson when its shot noise is on.
  if (cfg.nonideal.offset_shot_noise)
    for (int k = 0; k < 2; ++k)
      n.offset_e[k] = cfg.pixel.offset_voltage_V * cfg.pixel.source_follower_gain / golden::volts_per_electron(cfg, k);
  return n;
}

void LockinPixelKernel::reset(const ResetNoise& n, const LockinSimOptions& o, std::uint64_t frame, std::uint32_t row,
                              std::uint32_t column, bool merged) {
  clear();
  if (!o.noise) return;
  if (merged) return place_stream(o.seed, frame, row, column);
  rng_ = pixel_stream(pixel_stream_key(o.seed, frame, row, column));
  // Draw order: the pair (kTC FD1, kTC FD2), the pair (read FD1, read FD2)
  // (always consumed), then the Poisson counts.
  double z[4];
  standard_normal_pair(rng_, z[0], z[1]);
  standard_normal_pair(rng_, z[2], z[3]);
  for (int k = 0; k < 2; ++k) ktc_V_[k] = z[k] * n.ktc_fd_V[k], read_V_[k] = z[2 + k] * n.read_V;
  // Offset charge: drawn after the Gaussian pairs, so those keep their values; kept as its
  // deviation from the mean, which V_offset already carries.
  for (int k = 0; k < 2; ++k)
    if (n.offset_e[k] > 0) offset_dev_e_[k] = static_cast<double>(PoissonSampler(n.offset_e[k])(rng_)) - n.offset_e[k];
}

void LockinPixelKernel::collect(const TofLockinConfig& cfg, const LockinSimOptions& o, const LockinPixelStimulus& s,
                                bool led_on, double t_open, double t_now, long long period) {
  pg_e_ = generated_e(cfg, s, led_on, t_open, t_now, period, o.time_step_s);
}

double LockinPixelKernel::draw_poisson(const LockinSimOptions& o, double mean) {
  if (!o.noise) return mean;
  if (!(mean > 0.0)) return 0.0;
  // Aggregated frames reach 1e9 accumulations x up to ~1e16 electrons per period: past 2^63 the
  // integer draw overflows (undefined), and long before that a count is not exact in a double.
  // From 1e15 electrons on the Poisson law is Normal(mean, mean) to a skewness of 3e-8.
  if (mean > 1e15) return std::max(0.0, std::round(mean + std::sqrt(mean) * standard_normal(rng_)));
  return static_cast<double>(PoissonSampler(mean)(rng_));
}

void LockinPixelKernel::transfer(const TofLockinConfig& cfg, const LockinSimOptions& o, const LockinPixelStimulus& s,
                                 int window, double period_s) {
  if (window < 2) {
    fd_e_[window] += draw_poisson(o, s.tap_gain[window] * pg_e_);
  } else {
    const double leak = (1.0 - cfg.pixel.drain_efficiency) / 2.0;
    for (int k = 0; k < 2; ++k) {
      const double dark = (cfg.noise.dark_current_A + s.dark_extra_A[k]) * period_s / phys::kElementaryCharge_C;
      fd_e_[k] += draw_poisson(o, s.tap_gain[k] * leak * pg_e_ + dark);
    }
  }
  pg_e_ = 0;
}

void LockinPixelKernel::aggregate(const LockinSimOptions& o, const double m_total[2]) {
  for (int k = 0; k < 2; ++k) fd_e_[k] += draw_poisson(o, m_total[k]);
}

double LockinPixelKernel::adc_input_V(const TofLockinConfig& cfg, int tap) const {
  const double a = cfg.pixel.source_follower_gain;
  const double g = golden::volts_per_electron(cfg, tap);
  double swing = (fd_e_[tap] + offset_dev_e_[tap]) * g / a + cfg.pixel.offset_voltage_V;  // golden::tap_sample's form
  swing += ktc_V_[tap];
  swing = std::min(swing, cfg.pixel.saturation_voltage_V);
  return a * swing + read_V_[tap];
}

}  // namespace rangesim::systemc::lockin
