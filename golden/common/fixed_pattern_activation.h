#pragma once
// The chip's fixed pattern in golden (ls-conventional; core/nonideal.h). Every pixel of a chip has
// its own gain G = max(0, 1 + p z) on its photo swing (PRNU), dark current max(0, I_d + d z') (DSNU)
// and comparator offset o z'' at its input, z, z', z'' independent standard normals per pixel.
// The Monte Carlo draws a chip per trial (evaluate --trials), and the pixels' draws are
// independent, so within one frame access each pixel's first firing sampling is a mixture over
// its own draws and the pixels stay independent: golden's 1-bit moments (position_noise.h) hold
// with each pixel's P(F <= k) replaced by its mean over the draws.
//   - Comparator offset: A (min(n / c + o_kTC, V_sat) + r) + o z'' >= theta is the static noise r
//     with rms sqrt(sigma_r^2 + (o / A)^2): exact by variance addition (static_noise_V below).
//   - PRNU, DSNU: the mean electrons lambda_k(z, z') = c (G (V_sig g + V_bg) + V_d(z')) k / N; P(F <= k)
//     = E[f(lambda_k)] by composite 8-point Gauss-Legendre in z (and z') over +-8.5 (the normal's
//     mass beyond: 1.9e-17), split at the clip's kink (z = -1/p, z' = -I_d/d), in panels of at most
//     0.5 and a third of the width of f's step in z (f's step is sqrt(lambda + sigma_e^2) electrons
//     wide), so the step is resolved (tests compare it with an independent 4001-point integral).
// Not in golden: the fixed pattern with adc_bits > 1 (the delta-method path keeps the chip's mean
// pixel), and the correlation of one chip's frames (a frame average; docs/model-limits.md).
#include "core/ls_conventional/config.h"
#include "golden/common/activation_cdf.h"

namespace rangesim::golden {

class ActivationCache;

// rms of the pixel's static noise at the pixel (kTC, read, and the comparator offset / A_sf).
double static_noise_V(const LsConventionalConfig& cfg);

// Whether PRNU or DSNU is on (the comparator offset needs no quadrature).
bool fixed_pattern_spreads_mean(const LsConventionalConfig& cfg);

// P(activated) of a pixel whose mean photo electrons (signal and background) by the sampling at
// t = t_over_T T are photo_e, its dark electrons those of the config's dark current by then,
// averaged over the chip's PRNU and DSNU draws; threshold_e and sigma_e as activation_probability.
// `scale` refines the rule (tests: 4).
ActivationProbability fixed_pattern_activation(const LsConventionalConfig& cfg, ActivationCache& cache, double photo_e,
                                               double t_over_T, double threshold_e, double sigma_e, double scale = 1);

}  // namespace rangesim::golden
