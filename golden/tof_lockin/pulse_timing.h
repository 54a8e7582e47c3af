#pragma once
// Light pulse against the lock-in gate windows (thesis eq. 2.17-2.18, Fig. 2.10).
//
// One accumulation cycle of period T_rep = T0 / duty: PHASE1 opens TX1 over [0, T0] (aligned with
// the emitted pulse), PHASE2 opens TX2 over [T0, 2 T0], PHASE3 opens TXD over [2 T0, T_rep]. The
// received pulse is the emitted one delayed by T_D = 2 L / c. Its shape is a trapezoid of unit
// height and area T0 (FWHM T0): linear ramps of r = t_rise(10-90%) / 0.8 from 0 to 1 and back, so
// r = 0 is the thesis's rectangle. The part of the pulse inside a window is the difference of
// the pulse's cumulative area F at the window edges, exact for any r:
//   F(t) = t^2 / (2 r)                       0 <= t < r
//        = r/2 + (t - r)                     r <= t <= T0
//        = T0 - r/2 + u - u^2 / (2 r)        u = t - T0 in (0, r)
// For r = 0: tap1 = T0 - T_D, tap2 = T_D (eq. 2.17-2.18 without the I/q factor).
#include "core/tof_lockin_config.h"

namespace rangesim::golden {

// Light-on time (seconds at full intensity) of one received pulse inside each window.
struct PulseSplit {
  double tap1_s = 0;   // inside PHASE1 (TX1 -> FD1)
  double tap2_s = 0;   // inside PHASE2 (TX2 -> FD2)
  double drain_s = 0;  // the rest of the pulse (PHASE3, TXD)
};

// Repetition period T0 / duty.
double repetition_period_s(const LightPulseConfig& src);
// Round-trip delay T_D = 2 L / c.
double round_trip_delay_s(double distance_m);
// Unambiguous range c T0 / 2: the delay at which the pulse has left PHASE1 completely.
double max_range_m(const LightPulseConfig& src);
// 0 <= T_D <= T0: the ratio N2 / (N1 + N2) maps one-to-one on the delay. Outside it (negative
// delay, or T_D > T0 when N1 = 0 and the ratio sticks at 1) the range cannot be derived.
bool delay_in_range(const LightPulseConfig& src, double delay_s);
// Cumulative area F(t) of the unit-height pulse emitted at t = 0 (see above).
double pulse_area_before_s(const LightPulseConfig& src, double t_s);
// Split of one received pulse over the three phases.
PulseSplit split_pulse(const LightPulseConfig& src, double delay_s);

}  // namespace rangesim::golden
