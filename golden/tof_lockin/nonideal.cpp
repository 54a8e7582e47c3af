#include "golden/tof_lockin/nonideal.h"

#include <cmath>

#include "core/physics.h"
#include "golden/tof_lockin/pulse_timing.h"
#include "golden/tof_lockin/range_estimate.h"

namespace rangesim::golden {

FrameCharge add_light(FrameCharge c, const FrameCharge& more) {
  for (int k = 0; k < 2; ++k) c.signal_e[k] += more.signal_e[k];
  c.light_common_e += more.light_common_e;
  return c;
}

FrameCharge scene_frame_charge(const TofLockinConfig& cfg, double signal_A, double background_A, double delay_s) {
  FrameCharge c = frame_charge(cfg, signal_A, background_A, delay_s);
  const MultipathConfig& mp = cfg.nonideal.multipath;
  if (!mp.on()) return c;
  const double delay2_s = delay_s + mp.extra_path_m / phys::kSpeedOfLight_m_per_s;
  return add_light(c, frame_charge(cfg, mp.relative_amplitude * signal_A, 0.0, delay2_s));
}

double mixed_range_m(const TofLockinConfig& cfg, const std::vector<LightReturn>& returns) {
  FrameCharge c;
  for (const LightReturn& r : returns) c = add_light(c, frame_charge(cfg, r.signal_A, 0.0, r.delay_s));
  const double a = volts_per_electron(cfg, 0) * (c.signal_e[0] + c.light_common_e);
  const double b = volts_per_electron(cfg, 1) * (c.signal_e[1] + c.light_common_e);
  return max_range_m(cfg.source) * b / (a + b);
}

double offset_shot_var_V2(const TofLockinConfig& cfg, int tap) {
  if (!cfg.nonideal.offset_shot_noise) return 0.0;
  const double g = volts_per_electron(cfg, tap);                                         // A_sf q / C
  const double n_off = cfg.pixel.offset_voltage_V * cfg.pixel.source_follower_gain / g;  // C V_offset / q
  return g * g * n_off;
}

double fixed_pattern_range_m(const TofLockinConfig& cfg, const FrameCharge& c, double mu_a, double mu_b) {
  const FixedPatternConfig& fp = cfg.nonideal.fixed_pattern;
  const double K = max_range_m(cfg.source), s = mu_a + mu_b, s2 = s * s;
  const bool ambient = cfg.readout.ambient_subtraction;
  double x[2];  // the part of each tap a gain multiplies
  for (int k = 0; k < 2; ++k)
    x[k] = ambient ? (k == 0 ? mu_a : mu_b)
                   : volts_per_electron(cfg, k) * (c.signal_e[k] + c.light_common_e + c.background_e);
  const double m = fp.tap_mismatch_fraction;
  const double var_tap = K * K * m * m * (mu_a * mu_a * x[1] * x[1] + mu_b * mu_b * x[0] * x[0]) / (s2 * s2);
  const double prnu = fp.prnu_fraction * K * (mu_a * x[1] - mu_b * x[0]) / s2;
  double var_off = 0;
  if (!ambient) {
    const double n = static_cast<double>(cfg.gates.accumulations_per_frame);
    const double dsnu_V =
        volts_per_electron(cfg, 0) * fp.dsnu_rms * n * repetition_period_s(cfg.source) / phys::kElementaryCharge_C;
    const double o = std::hypot(dsnu_V, cfg.noise.fixed_pattern_rms_V);
    const double r = fixed_pattern_range_rms_m(K, mu_a, mu_b, o);
    var_off = r * r;
  }
  return std::sqrt(var_tap + prnu * prnu + var_off);
}

}  // namespace rangesim::golden
