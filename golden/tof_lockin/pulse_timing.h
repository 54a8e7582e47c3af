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
#include "core/tof_lockin/config.h"

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
// Split of one received pulse over the three windows of its own period (a tail past T_rep is
// counted as drained here; window_light_in_frame_s follows it into the next period).
PulseSplit split_pulse(const LightPulseConfig& src, double delay_s);

// Unit-height pulse shape at t_s after its emission: the trapezoid above, 0 outside [0, T0 + r].
double pulse_shape(const LightPulseConfig& src, double t_s);
// Light-on time of one pulse between t_a_s and t_b_s after its emission. step_s = 0: exact,
// F(t_b) - F(t_a). step_s > 0: the shape integrated numerically (midpoint rule on a grid of
// step_s anchored at t_a_s, the last cell cut at t_b_s), over the pulse's support only, so the
// cost is ~ (T0 + r) / step_s and the error O(step_s) at a rectangle's edges, O(step_s^2) with
// ramps (the time-step fidelity knob of the clock-level model).
double pulse_area_between_s(const LightPulseConfig& src, double t_a_s, double t_b_s, double step_s = 0);

// The pulse train of a frame of N periods against a window [t_a, t_b] (seconds from the start of
// each period) that recurs in every period. Pulse i is emitted at the start of period i and
// arrives T_D later. Its light is collected by whatever window is open when it arrives: a tail
// past T_rep (PHASE3 shorter than the pulse's ramp, e.g. duty 0.5 with a rise time) falls into
// the next period's PHASE1 and goes to FD1, since TX1 collects every photoelectron generated
// under the photogate while it is open (thesis 2.3, Fig. 2.10-2.11), whichever pulse it came
// from. Light arriving after the last period falls into the readout, where the photogate is
// drained (the PHASE3 profile, thesis 2.3) and nothing is collected.
// Light-on time inside the window of period `period` (0-based), from the pulses 0 .. period.
double window_light_in_period_s(const LightPulseConfig& src, double delay_s, double t_a_s, double t_b_s,
                                long long period, double step_s = 0);
// Light-on time inside the window summed over the periods 0 .. periods - 1 of a frame.
double window_light_in_frame_s(const LightPulseConfig& src, double delay_s, double t_a_s, double t_b_s,
                               long long periods, double step_s = 0);

}  // namespace rangesim::golden
