#pragma once
// Range from the two tap values and its mean and variance in closed form (thesis eq. 2.25, 4.9).
//
// With a = V1 - V_cal and b = V2 - V_cal the digitised tap values (ambient frame already
// subtracted when the readout does so) minus the offset the reconstruction assumes, and
// K = c T0 / 2, the estimate is L = K b / (a + b) = K f(a, b) (eq. 2.25). a and b are independent
// (separate FDs, resets, readouts) with means mu_a, mu_b and variances v_a, v_b. Moments of f by
// the delta method, s = mu_a + mu_b:
//   f_a = -mu_b / s^2, f_b = mu_a / s^2                    (first derivatives)
//   Var1 = K^2 (mu_b^2 v_a + mu_a^2 v_b) / s^4             (first order)
// which with v_i = N_i + 2 N_amb,i + 2 n_read^2 in electrons is the usual first-order lock-in formula
// sigma_L = (c T0 / 2) sqrt(N1^2 var(N2) + N2^2 var(N1)) / (N1 + N2)^2. Second order, for
// Gaussian a, b (f_aa = 2 mu_b / s^3, f_bb = -2 mu_a / s^3, f_ab = (mu_b - mu_a) / s^3, and
// third derivatives f_aaa = -6 mu_b / s^4, f_bbb = 6 mu_a / s^4, f_aab = (2 mu_a - 4 mu_b) / s^4,
// f_abb = (4 mu_a - 2 mu_b) / s^4):
//   E[f]  = f + (f_aa v_a + f_bb v_b) / 2 = f + (mu_b v_a - mu_a v_b) / s^3
//   Var f = Var1 + sum_ij (f_ij^2 / 2 + f_i f_ijj) v_i v_j
// The second-order terms are O(1 / SNR^2) relative, SNR = s / sqrt(v_a + v_b): they matter at the
// weakest detectable signals and are what a Monte Carlo of a few thousand frames resolves.
namespace rangesim::golden {

struct RangeMoments {
  double mean_m = 0;        // E[L], second order
  double var_m2 = 0;        // Var[L] of one frame, second order
  double var_first_m2 = 0;  // first-order part (the usual lock-in formula)
  double noise_free_m = 0;  // K mu_b / (mu_a + mu_b): L of the mean tap values
  double snr = 0;           // s / sqrt(v_a + v_b), validity of the expansion (>> 1)
};

// K_m = c T0 / 2; a, b: mean and variance of V1 - V_cal and V2 - V_cal. Requires mu_a + mu_b > 0.
RangeMoments range_moments(double K_m, double mu_a, double var_a, double mu_b, double var_b);

// The same moments without the expansion, for Gaussian a and b, given that the reconstruction
// gives a range at all: s = a + b >= s_min (> 0; the detection threshold). E[L | s] and E[L^2 | s]
// are closed forms (b given s is Gaussian: mean mu_b + (v_b / v_s)(s - mu_s), variance
// v_a v_b / v_s), so the moments are one-dimensional integrals over s, done by Gauss-Legendre
// quadrature to ~1e-10. Where the delta method fails (SNR of s below ~30: 1 / SNR^2 terms of
// percents, and the threshold cutting the tail of s) these are the moments a Monte Carlo of
// the kernels measures over its detected frames. var_first_m2 and snr as range_moments; p_range
// is P(s >= s_min).
struct ConditionalRangeMoments : RangeMoments {
  double p_range = 1;
};
ConditionalRangeMoments range_moments_given_range(double K_m, double mu_a, double var_a, double mu_b, double var_b,
                                                  double s_min);

// Rms range spread over pixels from a pixel-to-pixel offset of rms `fpn_V` on each tap (fixed
// pattern, not cancelled without the ambient frame): K sqrt(f_a^2 + f_b^2) fpn.
double fixed_pattern_range_rms_m(double K_m, double mu_a, double mu_b, double fpn_V);

}  // namespace rangesim::golden
