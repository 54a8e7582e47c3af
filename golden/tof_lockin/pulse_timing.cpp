#include "golden/tof_lockin/pulse_timing.h"

#include <algorithm>
#include <cmath>

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

double pulse_shape(const LightPulseConfig& src, double t_s) {
  const double T0 = src.pulse_width_s;
  const double r = src.rise_time_s / 0.8;
  if (r <= 0.0) return t_s >= 0.0 && t_s < T0 ? 1.0 : 0.0;
  if (t_s <= 0.0 || t_s >= T0 + r) return 0.0;
  if (t_s < r) return t_s / r;
  if (t_s <= T0) return 1.0;
  return (T0 + r - t_s) / r;
}

double pulse_area_between_s(const LightPulseConfig& src, double t_a_s, double t_b_s, double step_s) {
  if (step_s <= 0.0) return pulse_area_before_s(src, t_b_s) - pulse_area_before_s(src, t_a_s);
  const double end = src.pulse_width_s + std::max(0.0, src.rise_time_s / 0.8);  // support [0, end]
  const double hi_s = std::min(t_b_s, end);
  if (!(hi_s > t_a_s) || hi_s <= 0.0) return 0.0;
  // Cells [t_a + i h, t_a + (i + 1) h]: those ending before the pulse starts add nothing.
  long long i = t_a_s < 0.0 ? static_cast<long long>(std::floor(-t_a_s / step_s)) : 0;
  double sum = 0.0;
  for (;; ++i) {
    const double lo = t_a_s + static_cast<double>(i) * step_s;
    if (lo >= hi_s) break;
    const double hi = std::min(t_b_s, lo + step_s);
    sum += pulse_shape(src, 0.5 * (lo + hi)) * (hi - lo);
  }
  return sum;
}

namespace {

// Lags k (pulse emitted k periods before the window's period) whose light can reach [t_a, t_b]:
// [k_lo, k_hi). The pulse lasts T0 + r <= 2 T0 <= T_rep (config), so a few lags at most.
void lag_range(const LightPulseConfig& src, double delay_s, double t_a_s, double t_b_s, long long* k_lo,
               long long* k_hi) {
  const double Trep = repetition_period_s(src);
  const double end = src.pulse_width_s + std::max(0.0, src.rise_time_s / 0.8);
  const double lo = std::floor((delay_s - t_b_s) / Trep), hi = std::floor((delay_s + end - t_a_s) / Trep) + 1.0;
  constexpr double kMax = 4e18;  // far beyond any period count; keeps the casts defined
  *k_lo = static_cast<long long>(std::clamp(lo, 0.0, kMax));
  *k_hi = static_cast<long long>(std::clamp(hi, 0.0, kMax));
}

// Light of the pulse emitted k periods before the window's period.
double lag_light_s(const LightPulseConfig& src, double delay_s, double t_a_s, double t_b_s, long long k,
                   double step_s) {
  const double shift = static_cast<double>(k) * repetition_period_s(src) - delay_s;
  return pulse_area_between_s(src, t_a_s + shift, t_b_s + shift, step_s);
}

}  // namespace

double window_light_in_period_s(const LightPulseConfig& src, double delay_s, double t_a_s, double t_b_s,
                                long long period, double step_s) {
  long long k_lo, k_hi;
  lag_range(src, delay_s, t_a_s, t_b_s, &k_lo, &k_hi);
  double sum = 0.0;
  for (long long k = k_lo; k < std::min(k_hi, period + 1); ++k)
    sum += lag_light_s(src, delay_s, t_a_s, t_b_s, k, step_s);
  return sum;
}

double window_light_in_frame_s(const LightPulseConfig& src, double delay_s, double t_a_s, double t_b_s,
                               long long periods, double step_s) {
  long long k_lo, k_hi;
  lag_range(src, delay_s, t_a_s, t_b_s, &k_lo, &k_hi);
  // Lag k reaches the window in periods k .. N - 1: N - k times.
  double sum = 0.0;
  for (long long k = k_lo; k < std::min(k_hi, periods); ++k)
    sum += static_cast<double>(periods - k) * lag_light_s(src, delay_s, t_a_s, t_b_s, k, step_s);
  return sum;
}

}  // namespace rangesim::golden
