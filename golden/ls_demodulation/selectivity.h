#pragma once
// Selectivity of the demodulating pixel: response to background modulated at harmonics k f0,
// and the settling of the LPF subtraction after a background step.
//
// Harmonics, linearised (closed form): a background I_dc + a cos(2 pi k f0 t + theta) passes the
// subtraction with H_k = alpha [(1 + eps) - 1 / (1 + j 2 pi k f0 tau)], the log with gain
// beta s / I_op (I_op = I_off + alpha eps I_dc at the background-only operating point), and the
// correlator with the MPY weight w(t) = +1/C1 (MPY+), -1/C2 (MPY-): the worst-phase output is
// N g_m |H_k| a beta s / I_op |int_0^T0 w(t) e^{j 2 pi k f0 t} dt|. For a 50% reference the weight's
// even Fourier coefficients vanish (|c_k| ~ |sin(pi k D)| / k), whatever C1 and C2: even
// harmonics are ideally rejected; a duty D gives |c_2 / c_1| = |cos(pi D)|.
//
// Exact chain: a square-wave background component at k f0 (50% duty) through the full nonlinear
// chain, worst phase over 32 delays, the background-only output subtracted.
#include "core/ls_demodulation/config.h"

namespace rangesim::golden {

// Worst-phase output (V) per ampere of a sinusoidal background component at k f0 (linearised).
double harmonic_gain_V_per_A(const LsDemodulationConfig& cfg, double background_A, int k);

// 20 log10 of the response at k f0 relative to k = 1, linearised; -inf when ideally rejected.
double harmonic_selectivity_dB(const LsDemodulationConfig& cfg, double background_A, int k);

// Same through the exact chain with a square background component of amplitude `amplitude_A`.
double harmonic_selectivity_square_dB(const LsDemodulationConfig& cfg, double background_A, double amplitude_A, int k);

// Reference duty D with |cos(pi D)| = 10^(dB/20): the duty that explains an even-harmonic
// suppression of `dB` (< 0) by the weight's second coefficient.
double duty_for_even_harmonic_dB(double dB);

// Background step I1 -> I2 at t = 0, LPF settled on I1 before: I_mod(t) - I_mod(inf) relative
// to alpha (I2 - I1), = e^{-t/tau} (closed form).
double step_residual_fraction(const LsDemodulationConfig& cfg, double time_s);
// Time for that residual to fall to `fraction`: tau ln(1 / fraction).
double step_settling_time_s(const LsDemodulationConfig& cfg, double fraction);
// Correlator output D (V) of a window starting `delay_s` after the step, minus the settled output
// (exact chain, no beam).
double step_correlator_error_V(const LsDemodulationConfig& cfg, double from_A, double to_A, double delay_s);

}  // namespace rangesim::golden
