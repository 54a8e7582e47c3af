#include "golden/tof_lockin/pulse_timing.h"

#include <algorithm>

#include "core/physics.h"

namespace rangesim::golden {

double repetition_period_s(const LightPulseConfig& src) { return src.pulse_width_s / src.duty_cycle; }

double round_trip_delay_s(double distance_m) { return 2.0 * distance_m / phys::kSpeedOfLight_m_per_s; }

double max_range_m(const LightPulseConfig& src) { return phys::kSpeedOfLight_m_per_s * src.pulse_width_s / 2.0; }

bool delay_in_range(const LightPulseConfig& src, double delay_s) {
  // 1e-12 relative slack: T_D = 2 (c T0 / 2) / c must count as T0 despite rounding.
  return delay_s >= 0.0 && delay_s <= src.pulse_width_s * (1.0 + 1e-12);
}

double pulse_area_before_s(const LightPulseConfig& src, double t_s) {
  const double T0 = src.pulse_width_s;
  const double r = src.rise_time_s / 0.8;  // full 0-100 % ramp of a linear edge
  if (t_s <= 0.0) return 0.0;
  if (r <= 0.0) return std::min(t_s, T0);  // rectangle
  if (t_s < r) return t_s * t_s / (2.0 * r);
  if (t_s <= T0) return r / 2.0 + (t_s - r);
  const double u = t_s - T0;
  if (u < r) return T0 - r / 2.0 + u - u * u / (2.0 * r);
  return T0;
}

PulseSplit split_pulse(const LightPulseConfig& src, double delay_s) {
  const double T0 = src.pulse_width_s;
  const auto area = [&](double t) { return pulse_area_before_s(src, t - delay_s); };
  PulseSplit s;
  s.tap1_s = area(T0) - area(0.0);
  s.tap2_s = area(2.0 * T0) - area(T0);
  // The pulse's whole area is T0; what is not in the two open windows is drained (this includes
  // a pulse arriving before PHASE1 opens, which only a negative delay could do).
  s.drain_s = std::max(0.0, T0 - s.tap1_s - s.tap2_s);
  return s;
}

}  // namespace rangesim::golden
