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
#include <cstddef>
#include <limits>
#include <vector>

#include "core/ls_demodulation/config.h"

namespace rangesim::golden {

// One piece of a period: constant photocurrent, one integrator connected. I_dc and I_ac are kept
// apart beside their rounded sum: the LPF state is carried as its offset from I_dc, so the lag
// I_avg - I_pd (the beam's share) is exact to ulp(I_ac), not ulp(I_dc), under a huge background.
struct Segment {
  double duration_s = 0;
  double photocurrent_A = 0;  // I_pd = I_dc + I_ac on this piece (dark current included), rounded
  int branch = +1;            // +1: MPY+ (C1) integrates, -1: MPY- (C2)
  double dc_A = 0;            // I_dc: the level that is constant over the period (background + dark)
  double ac_A = 0;            // I_ac: the modulated part on this piece (beam)
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
  double diff_V = 0;            // V_out+ - V_out- at the end of the window (noise-free)
  double plus_V = 0;            // V_out+ swing (from its reset level)
  double minus_V = 0;           // V_out- swing
  double peak_abs_V = 0;        // largest |swing| of either integrator at a segment end
  double shot_var_V2 = 0;       // shot-noise variance of diff_V
  double clipped_fraction = 0;  // fraction of the window where I_off + I_mod sat on the floor
  double lpf_end_A = 0;         // I_avg at the end of the window
  // shot_var_V2 split by where the noise enters D (the clock-level kernel draws each part once
  // when it aggregates the window): charge on C1, on C2, and the LPF's memory of before the window.
  double shot_var_plus_V2 = 0;
  double shot_var_minus_V2 = 0;
  double shot_var_past_V2 = 0;
};

// The period repeated `periods` times with the LPF in its periodic steady state (the beam and
// background have been on for many tau: eq. 2.9's I_avg = mean I_pd). Identical periods are
// aggregated exactly: O(segments x log periods), so correlator.cycles up to 1e9 costs microseconds.
CorrelatorOutput correlate_periodic(const LsDemodulationConfig& cfg, const std::vector<Segment>& period, int periods);

// Same, with the LPF starting from `lpf_start_A` at the window start (transients, e.g. a
// background step); noise from before the window is taken at the level lpf_start_A. Steps the
// periods until the LPF transient is below rounding (at most ~40 tau f0 periods), then
// aggregates the identical rest: O(segments x min(periods, 40 tau f0 + log periods)).
CorrelatorOutput correlate_from(const LsDemodulationConfig& cfg, const std::vector<Segment>& period, int periods,
                                double lpf_start_A);
// The same with every segment of the window stepped: O(segments x periods) time and memory; the
// reference the aggregated forms are tested against.
CorrelatorOutput correlate_stepped(const LsDemodulationConfig& cfg, const std::vector<Segment>& period, int periods,
                                   double lpf_start_A);

// Periodic steady state of the LPF at the period start: I_avg(0) = b / (1 - e^{-T0/tau}).
double lpf_periodic_start_A(const LsDemodulationConfig& cfg, const std::vector<Segment>& period);
// The same as an offset from the period's I_dc (period[0].dc_A): I_avg(0) = dc_A + this, exactly
// the LPF of the I_ac parts (and of dc_A differences between segments).
double lpf_periodic_offset_A(const LsDemodulationConfig& cfg, const std::vector<Segment>& period);

// The LPF lag I_avg - I_pd on a segment from the LPF state held as its offset from period[0].dc_A.
inline double lpf_lag_A(double lpf_offset_A, const Segment& s, double dc0_A) {
  return lpf_offset_A - ((s.dc_A - dc0_A) + s.ac_A);
}
// The LPF offset after segment s (exact exponential relaxation towards I_pd - dc0).
double lpf_offset_after_A(const LsDemodulationConfig& cfg, double lpf_offset_A, const Segment& s, double dc0_A,
                          double duration_s);

// Shot noise of a periodic window, for the clock-level kernel: one period of golden's backward
// recursion G(end of period) -> G(start) with its variance, and its powers for N periods
// (binary powering: O(S log N) time, O(S + log N) memory).
class PeriodicShotNoise {
 public:
  // k: the noise kernel per segment of one period (V per A s of i_mod; golden's forward pass).
  PeriodicShotNoise(const LsDemodulationConfig& cfg, const std::vector<Segment>& period, std::vector<double> k,
                    long long periods);
  // G (V per A s, as k) at the end of a period that `after` more periods follow (G = 0 at the window end).
  double g_end(long long after) const;
  // Variance added to D by segment j's shot noise given G at its end; G becomes G at its start.
  double segment_var_V2(std::size_t j, double& G) const;
  // `periods` periods ending the window: variance on C1, on C2, and G at their start.
  struct Window {
    double plus_V2 = 0, minus_V2 = 0, g_start = 0;
  };
  Window window(long long periods) const;

 private:
  // One or more periods backwards: G_start = a + c G_end; variance added (per branch: 0 = C1,
  // 1 = C2) v0 + v1 G_end + v2 G_end^2.
  struct Map {
    double a = 0, c = 1;
    double v0[2] = {0, 0}, v1[2] = {0, 0}, v2[2] = {0, 0};
  };
  static Map compose(const Map& later, const Map& earlier);
  Map power(long long n) const;

  std::vector<Segment> period_;  // one period
  std::vector<double> k_;        // noise kernel per segment
  double alpha_ = 0, eps_ = 0, tau_ = 0;
  std::vector<Map> pow2_;  // the one-period map composed 2^i times, i < log2(periods) + 1
};

// Noise kernel k_j of the linearised chain per segment of one period with the LPF starting at
// offset `lpf_offset_A` from period[0].dc_A (golden's forward pass, exposed for the kernel).
std::vector<double> period_noise_kernel(const LsDemodulationConfig& cfg, const std::vector<Segment>& period,
                                        double lpf_offset_A);
// The variance of the LPF's memory of shot noise from before the window (at mean current
// `past_mean_A`), given G at the window start.
double past_shot_var_V2(const LsDemodulationConfig& cfg, double past_mean_A, double g_start);

// int_0^L ln(max(c0 + c1 e^{-s/tau}, floor) / ref) ds, the same of 1/(c0 + c1 e^{-s/tau}) over
// the unclipped part, and the clipped time (exposed for tests).
struct LogIntegral {
  double ln_s = 0;         // int ln(max(f, floor) / ref) ds
  double inv_s_per_A = 0;  // int 1{f > floor} / f ds
  double clipped_s = 0;    // time with f <= floor
};
// c0_minus_ref_A: c0 - ref exactly (c0 = ref + alpha eps I here); NaN: computed as c0 - ref.
LogIntegral log_integral(double c0_A, double c1_A, double tau_s, double length_s, double floor_A, double ref_A,
                         double c0_minus_ref_A = std::numeric_limits<double>::quiet_NaN());

// kTC variance of the difference: kT/C1 + kT/C2 (each integrator reset once per decision).
double ktc_variance_V2(const LsDemodulationConfig& cfg);

}  // namespace rangesim::golden
