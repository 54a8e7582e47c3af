#pragma once
// Photodiode pixel with source follower (thesis eq. 3.1-3.4), in the thesis's voltage units.
//
// The photocurrent I discharges the photodiode capacitance C during the integration time T, so the
// swing grows linearly: V(t) = I t / C (eq. 3.1). The evaluation is parameterised by the swings at
// the end of integration (V_sig at the spot peak, V_bg for the background), so these helpers
// convert between currents, voltages and electron counts. The source follower scales the swing by
// A_sf (eq. 3.4) before the comparator sees it.
#include "core/ls_conventional/config.h"

namespace rangesim::golden {

// eq. 3.1: V = I t / C.
double voltage_from_current_V(double current_A, double time_s, double capacitance_F);
// Inverse of eq. 3.1: the current that gives `voltage_V` after `time_s`.
double current_from_voltage_A(double voltage_V, double time_s, double capacitance_F);

// Dark-current swing at the end of integration, I_dark T / C.
double dark_voltage_V(const PixelConfig& pixel);
// Electrons per volt of swing on the photodiode, C / q (shot noise lives in electrons).
double electrons_per_volt(const PixelConfig& pixel);
// kTC reset noise sqrt(kT/C), rms volts: sampled once at reset, then frozen for the frame.
double ktc_noise_V(const PixelConfig& pixel);
// Static per-frame offset noise: kTC and read noise (1/f-dominated at microsecond scale, so it does
// not change between the samplings of one frame) combined in quadrature, rms volts.
double static_noise_V(const PixelConfig& pixel);

// Noise-free swing of a pixel at time t (0..T): the swing grows linearly during integration,
// v(t) = (V_sig g + V_bg + V_dark) t / T, with g the spot profile at the pixel (peak 1).
double pixel_swing_V(double signal_V, double profile, double background_V, double dark_V, double t_over_T);

// eq. 3.4 without noise: the source follower applies A_sf to the swing.
double output_voltage_V(const PixelConfig& pixel, double swing_V);

// eq. 3.3: the pixel saturates when its swing exceeds V_sat.
bool saturates(const PixelConfig& pixel, double swing_V);

}  // namespace rangesim::golden
