#include "golden/tof_lockin/tap_charge.h"

#include <cmath>

#include "core/physics.h"
#include "golden/tof_lockin/nonideal.h"
#include "golden/tof_lockin/pulse_timing.h"

namespace rangesim::golden {

namespace {

double fd_capacitance_F(const TofLockinConfig& cfg, int tap) {
  return tap == 0 ? cfg.pixel.fd1_capacitance_F : cfg.pixel.fd2_capacitance_F;
}

}  // namespace

FrameCharge frame_charge(const TofLockinConfig& cfg, double signal_A, double background_A, double delay_s) {
  const double q = phys::kElementaryCharge_C;
  const double T0 = cfg.source.pulse_width_s;
  const double Trep = repetition_period_s(cfg.source);
  const double phase3_s = Trep - 2.0 * T0;  // >= 0: duty <= 0.5 by the schema
  const long long n_acc = cfg.gates.accumulations_per_frame;
  const double n = static_cast<double>(n_acc);
  const double eta = cfg.pixel.charge_separation;
  const double leak = (1.0 - cfg.pixel.drain_efficiency) / 2.0;  // to each tap
  // Light-on time of the frame's pulse train in each window, summed over the periods (a tail past
  // T_rep lands in the next period's PHASE1; pulse_timing.h).
  const double light_s[3] = {window_light_in_frame_s(cfg.source, delay_s, 0.0, T0, n_acc),
                             window_light_in_frame_s(cfg.source, delay_s, T0, 2.0 * T0, n_acc),
                             window_light_in_frame_s(cfg.source, delay_s, 2.0 * T0, Trep, n_acc)};

  FrameCharge c;
  c.signal_e[0] = eta * signal_A * light_s[0] / q;
  c.signal_e[1] = eta * signal_A * light_s[1] / q;
  // Deep electrons: (1 - eta) of the pulse's charge, spread uniformly over the period.
  const double deep_e = (1.0 - eta) * signal_A * T0 * n / q;
  const double deep_per_tap_e = deep_e * T0 / Trep;
  const double deep_drained_e = deep_e * phase3_s / Trep;
  const double signal_drained_e = eta * signal_A * light_s[2] / q;
  c.light_common_e = deep_per_tap_e + leak * (deep_drained_e + signal_drained_e);
  c.background_e = background_A * n * (T0 + leak * phase3_s) / q;
  c.dark_e = cfg.noise.dark_current_A * n * Trep / q;
  return c;
}

double volts_per_electron(const TofLockinConfig& cfg, int tap) {
  return cfg.pixel.source_follower_gain * phys::kElementaryCharge_C / fd_capacitance_F(cfg, tap);
}

double ktc_noise_V(const TofLockinConfig& cfg, int tap) {
  if (cfg.readout.cds_enabled) return 0.0;
  return cfg.pixel.source_follower_gain *
         std::sqrt(phys::kBoltzmann_J_per_K * cfg.noise.temperature_K / fd_capacitance_F(cfg, tap));
}

TapSample tap_sample(const TofLockinConfig& cfg, int tap, double electrons) {
  const double g = volts_per_electron(cfg, tap);
  const double ktc = ktc_noise_V(cfg, tap);
  TapSample s;
  s.fd_swing_V = electrons * g / cfg.pixel.source_follower_gain + cfg.pixel.offset_voltage_V;
  s.mean_V = cfg.pixel.source_follower_gain * s.fd_swing_V;
  s.sigma_V = std::sqrt(g * g * electrons + ktc * ktc + cfg.noise.read_noise_V * cfg.noise.read_noise_V +
                        offset_shot_var_V2(cfg, tap));
  return s;
}

bool tap_saturates(const TofLockinConfig& cfg, const TapSample& s) {
  return s.fd_swing_V > cfg.pixel.saturation_voltage_V || s.mean_V > cfg.readout.adc_full_scale_V;
}

}  // namespace rangesim::golden
