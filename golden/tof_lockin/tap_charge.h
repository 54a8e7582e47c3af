#pragma once
// Charge on the two floating diffusions after one frame of N_acc accumulation cycles, and its
// voltage and noise at the column ADC input (thesis eq. 2.17-2.19, 2.23-2.25).
//
// Per cycle (pulse split from pulse_timing.h, I_s = signal photocurrent during the pulse, I_b =
// background photocurrent, eta = charge_separation, eps = drain_efficiency, T_rep = T0 / duty):
//   signal, tap k:      eta I_s t_k / q                      (t_k = light-on time in window k)
//   deep electrons:     (1 - eta) I_s T0 arrive uniformly over T_rep (slow diffusion from deep
//                       in the epi layer): each tap receives the fraction T0 / T_rep of them
//   background, tap k:  I_b T0 / q                           (both windows are open for T0)
//   PHASE3 leakage:     (1 - eps) / 2 of everything generated while TXD drains goes to each tap
//   dark:               I_dark T_rep / q into each FD (the wait until readout is not modelled)
// times N_acc, with one exception: t_k sums the frame's pulse train over the periods
// (window_light_in_frame_s), so a pulse tail past T_rep counts in the next period's PHASE1 and
// the last pulse's tail past the accumulation is not collected. Everything but the tap-specific signal is common to
// both taps. The thesis's V_offset (eq. 2.25) is `offset_voltage_V`, a constant FD offset present in every frame.
//
// At the ADC input, V_k = A_sf (q N_k / C_k + V_offset). Noise per sample (one readout of a tap):
// Poisson shot noise of N_k (A_sf q / C_k)^2 N_k, kTC reset noise A_sf^2 k T / C_k (unless CDS),
// read noise sigma_read^2, and the offset charge's own shot noise A_sf^2 q V_offset / C_k
// (golden/tof_lockin/nonideal.h). The ambient frame (LED off) has the same windows without the light.
#include "core/tof_lockin/config.h"

namespace rangesim::golden {

// Mean electrons on each FD after one frame.
struct FrameCharge {
  double signal_e[2] = {0, 0};  // tap-specific signal: eta I_s t_k N / q
  double light_common_e = 0;    // light-induced, equal in both taps (deep electrons, PHASE3 leakage)
  double background_e = 0;      // background in each tap (windows + PHASE3 leakage)
  double dark_e = 0;            // dark current in each FD
  double total_e(int k) const { return signal_e[k] + light_common_e + background_e + dark_e; }
  double ambient_e() const { return background_e + dark_e; }  // same frame with the LED off
};

// Mean charge of the LED-on frame for signal photocurrent I_s, background I_b and delay T_D.
FrameCharge frame_charge(const TofLockinConfig& cfg, double signal_A, double background_A, double delay_s);

// Volts at the ADC input per electron on FD k: A_sf q / C_k.
double volts_per_electron(const TofLockinConfig& cfg, int tap);
// kTC reset noise at the ADC input, rms volts (0 with CDS).
double ktc_noise_V(const TofLockinConfig& cfg, int tap);

// One readout of one tap: mean and Gaussian-approximated rms at the ADC input.
struct TapSample {
  double mean_V = 0;
  double sigma_V = 0;
  double fd_swing_V = 0;  // q N / C + V_offset on the FD (for saturation)
};
TapSample tap_sample(const TofLockinConfig& cfg, int tap, double electrons);

// The FD swing exceeds V_sat, or the ADC input exceeds its full scale (the code clips).
bool tap_saturates(const TofLockinConfig& cfg, const TapSample& s);

}  // namespace rangesim::golden
