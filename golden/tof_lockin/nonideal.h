#pragma once
// tof-lockin's non-idealities in closed form (core/nonideal.h, docs/model-limits.md).
//
// Returns: the taps' charge is linear in the light, so light from several surfaces (a second
// return by multipath, a neighbour's surface by the point spread at a depth step) adds per return:
// N_k = sum_j frame_charge(I_j, T_D,j).signal_e[k] + common. A pixel mixing two depths reports
// K b / (a + b) of the summed charges: between the two ranges, weighted by each return's charge
// (a flying pixel), not the range of either.
//
// Fixed pattern, the rms over pixels of the range error that is the same in every frame, at
// first order in the spreads (each independent, added in quadrature). With a = mu_a, b = mu_b the
// tap values the estimator L = K b / (a + b) sees, s = a + b, and x_k the part of tap k a gain
// multiplies (light-induced, and the background when no ambient frame is subtracted):
//   tap gain mismatch m (each tap):   K m sqrt(a^2 x_b^2 + b^2 x_a^2) / s^2  (= sqrt 2 K m a b / s^2
//                                     with the ambient frame, where x = mu)
//   PRNU p (the photogate, both taps): K p |a x_b - b x_a| / s^2: 0 with the ambient frame
//                                     (a common gain cancels in the ratio)
//   DSNU d (dark current of each FD) and noise.fixed_pattern_rms_V: offsets per tap,
//                                     K sqrt(a^2 + b^2) o / s^2 with o = d N_acc T_rep A_sf / C;
//                                     cancelled by the ambient frame (the same dark charge)
// These do not average over frames: accuracy(N) = sqrt(bias^2 + fpn^2 + var_1 / N).
//
// Offset charge: V_offset on an FD is q n_off / C with n_off = C V_offset / q deep electrons per
// frame (thesis 2.3), Poisson, so it adds A_sf^2 q V_offset / C to the variance of every sample.
#include <vector>

#include "core/tof_lockin/config.h"
#include "golden/tof_lockin/tap_charge.h"

namespace rangesim::golden {

struct LightReturn {
  double signal_A = 0;  // photocurrent during the received pulse
  double delay_s = 0;   // round-trip delay
};

// The light of `more` (its signal and light-common charge) added to `c`.
FrameCharge add_light(FrameCharge c, const FrameCharge& more);

// The frame charge of a pixel of the evaluation: the direct return plus, with multipath on, the
// second return (multipath.relative_amplitude x I_s, delayed by multipath.extra_path_m / c).
FrameCharge scene_frame_charge(const TofLockinConfig& cfg, double signal_A, double background_A, double delay_s);

// Noise-free range of a pixel seeing `returns` (ambient frame subtracted, no V_cal): eq. 2.25 on
// the summed charges.
double mixed_range_m(const TofLockinConfig& cfg, const std::vector<LightReturn>& returns);

// Variance at the ADC input of one sample from the offset charge's shot noise (0 when off).
double offset_shot_var_V2(const TofLockinConfig& cfg, int tap);

// Rms over pixels of the fixed range error (above); mu: the tap values of the estimator.
double fixed_pattern_range_m(const TofLockinConfig& cfg, const FrameCharge& c, double mu_a, double mu_b);

}  // namespace rangesim::golden
