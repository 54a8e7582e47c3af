#pragma once
// Demodulating pixel of ls-demodulation (thesis [27], eq. 2.8-2.13 / 3.12-3.17), noise-free mean
// and shot-noise variance of the correlator output V_out+ - V_out- after N periods.
//
// Chain, for a photocurrent I_pd(t) that is constant on each segment of a period:
//   LPF        tau dI_avg/dt = I_pd - I_avg            exact: I_avg = I + (I_avg(a) - I) e^{-(t-a)/tau}
//   subtract   I_mod = alpha (1 + eps) I_pd - alpha I_avg   (eq. 2.10 prints alpha' I_dc; with I_dc the
//              output would hold no signal, so the copy is of I_pd; eps = mirror mismatch)
//   log        V_mod = beta s ln(max(I_off + I_mod, I_leak) / I_off)   (eq. 2.11; referenced to the
//              output at I_mod = 0, s = slope_V; the floor I_leak guards log of zero or negative
//              currents: a current-mode stage cannot sink more than its bias, the swing clips)
//   integrate  dV_+/dt = g_m V_mod / C1 while MPY+, dV_-/dt = g_m V_mod / C2 while MPY-  (eq. 2.13)
// On a segment I_off + I_mod = c0 + c1 e^{-s/tau} exactly; its log is integrated by 8-point
// Gauss-Legendre (panels of <= 2 tau, a flat tail once e^{-s/tau} is gone), split exactly where
// the floor is crossed.
//
// Shot noise (two-sided PSD q I_pd) passes the chain linearised about the mean: the output is
// y = int K(u) i(u) du with K = alpha (1+eps) k(u) - alpha int_u^T k(t) e^{-(t-u)/tau} dt / tau,
// k = +-g_m beta s / (C I_log) (0 where clipped). With k constant per segment (its segment mean:
// first order in the LPF ripple L / tau) K is A + B e^{-(b-u)/tau} per segment and
// Var = q sum I_j int K^2 du in closed form, plus the LPF's memory of noise before the window.
#include <limits>
#include <vector>

#include "core/ls_demodulation_config.h"

namespace rangesim::golden {

// One piece of a period: constant photocurrent, one integrator connected.
struct Segment {
  double duration_s = 0;
  double photocurrent_A = 0;  // I_pd = I_dc + I_ac on this piece (dark current included)
  int branch = +1;            // +1: MPY+ (C1) integrates, -1: MPY- (C2)
};

// A square-wave current component: on with `amplitude_A` for `duty` of each of its periods,
// at `harmonic` x f0, its on-edge delayed by `delay_periods` of its own period.
struct SquareComponent {
  double amplitude_A = 0;
  int harmonic = 1;
  double duty = 0.5;
  double delay_periods = 0;
};

// Segments of one correlation period [0, 1/f0): constant current `dc_A` plus the components,
// cut at every edge of a component and of MPY+ (on [phase/2pi, phase/2pi + D_r) of the period).
std::vector<Segment> period_segments(const LsDemodulationConfig& cfg, double dc_A,
                                     const std::vector<SquareComponent>& components);

// The usual operating point: background + dark current, the beam as a square at f0 with the
// source duty cycle (beam_A = beam-on photocurrent of this pixel).
std::vector<Segment> pixel_segments(const LsDemodulationConfig& cfg, double beam_A, double background_A);

struct CorrelatorOutput {
  double diff_V = 0;          // V_out+ - V_out- at the end of the window (noise-free)
  double plus_V = 0;          // V_out+ swing (from its reset level)
  double minus_V = 0;         // V_out- swing
  double peak_abs_V = 0;      // largest |swing| of either integrator at a segment end
  double shot_var_V2 = 0;     // shot-noise variance of diff_V
  double clipped_fraction = 0;  // fraction of the window where I_off + I_mod sat on the floor
  double lpf_end_A = 0;       // I_avg at the end of the window
};

// The period repeated `periods` times with the LPF in its periodic steady state (the beam and
// background have been on for many tau: eq. 2.9's I_avg = mean I_pd). Identical periods are
// aggregated exactly: O(segments x log periods), so correlator.cycles up to 1e9 costs microseconds.
CorrelatorOutput correlate_periodic(const LsDemodulationConfig& cfg, const std::vector<Segment>& period, int periods);

// Same, with the LPF starting from `lpf_start_A` at the window start (transients, e.g. a
// background step); noise from before the window is taken at the level lpf_start_A. Steps every
// segment of the window: O(segments x periods) time and memory.
CorrelatorOutput correlate_from(const LsDemodulationConfig& cfg, const std::vector<Segment>& period, int periods,
                                double lpf_start_A);

// Periodic steady state of the LPF at the period start: I_avg(0) = b / (1 - e^{-T0/tau}).
double lpf_periodic_start_A(const LsDemodulationConfig& cfg, const std::vector<Segment>& period);

// int_0^L ln(max(c0 + c1 e^{-s/tau}, floor) / ref) ds, the same of 1/(c0 + c1 e^{-s/tau}) over
// the unclipped part, and the clipped time (exposed for tests).
struct LogIntegral {
  double ln_s = 0;       // int ln(max(f, floor) / ref) ds
  double inv_s_per_A = 0;  // int 1{f > floor} / f ds
  double clipped_s = 0;  // time with f <= floor
};
// c0_minus_ref_A: c0 - ref exactly (c0 = ref + alpha eps I here); NaN: computed as c0 - ref.
LogIntegral log_integral(double c0_A, double c1_A, double tau_s, double length_s, double floor_A, double ref_A,
                         double c0_minus_ref_A = std::numeric_limits<double>::quiet_NaN());

// kTC variance of the difference: kT/C1 + kT/C2 (each integrator reset once per decision).
double ktc_variance_V2(const LsDemodulationConfig& cfg);

}  // namespace rangesim::golden
