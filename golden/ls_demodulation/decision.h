#pragma once
// Comparator decision of one demodulating pixel (eq. 2.12) under noise, and the classification of
// an operating point (why range can or cannot be derived).
//
// Noise on D = V_out+ - V_out- (Gaussian; shot noise is many electrons per window):
//  - independent per decision: shot noise through the chain (front_end.h), kTC of C1 and C2
//    (both integrators are reset before each decision), fixed-pattern offset (see docs: taken as
//    per-decision, an optimistic simplification; 0 in the preset);
//  - the chip's fixed pattern (fixed_pattern.*): comparator offset, PRNU and DSNU. Over chips
//    (the spot falls on other pixels in every frame access of a scene, and `evaluate --trials`
//    draws a chip per trial) each pixel's pattern is an independent draw, so in one decision it
//    is one more independent term: the comparator offset adds its variance; PRNU (gain G = 1 +
//    p z on beam and background) and DSNU (dark current + sigma_d z') move D itself, and D is
//    taken at the 5 x 3 Gauss-Hermite nodes of (z, z'): mean and variance of D over chips exact
//    for D up to degree 4 in z and 2 in z' (the log stage's curvature: the second-order terms a
//    linearisation misses), their distribution taken as Gaussian (exact where D is linear in the
//    draws). fixed_pattern.h keeps the chip's part apart where frames are averaged;
//  - common to all decisions of a frame: read noise of the source followers / comparator,
//    1/f-dominated at microsecond scale (as in ls-conventional), so repeated decisions within a
//    frame cannot average it away, frames can.
// P(active) = P(D + n >= V_cmp) = Phi((mu + o - V_cmp) / sigma_ind) given the common offset o;
// expectations over o use 9-node Gauss-Hermite quadrature.
#include <array>
#include <string>

#include "core/ls_demodulation/config.h"
#include "golden/ls_demodulation/front_end.h"

namespace rangesim::golden {

enum class DemodDetect {
  Detectable,            // the spot peak reaches V_cmp, nothing saturates, background does not activate
  BelowThreshold,        // noise-free D at the spot peak stays below V_cmp
  Saturated,             // an integrator swing exceeds V_sat (background alone or with the spot)
  BackgroundActivation,  // background alone reaches V_cmp, or its noise activates rows too often
};
const char* to_string(DemodDetect d);

// Mean and noise of D for one pixel.
struct PixelDecision {
  CorrelatorOutput out;            // noise-free chain output of the nominal pixel (no fixed pattern)
  double mean_V = 0;               // E[D] over chips (PRNU, DSNU); out.diff_V without them
  double sigma_independent_V = 0;  // rms of the per-decision noise, the chip's part included
  double sigma_chip_V = 0;         // rms of the chip's part alone (comparator offset, PRNU, DSNU)
  double sigma_common_V = 0;       // rms of the frame-common noise
};
PixelDecision pixel_decision(const LsDemodulationConfig& cfg, double beam_A, double background_A);

// Upper tail Phi((mu - thr) / sigma) with its complement, accurate in both tails.
struct Tail {
  double p = 0, q = 1;
};
Tail activation(double mean_V, double threshold_V, double sigma_V);

// Nodes and weights of E[f(o)], o ~ N(0, sigma^2) (9-node Gauss-Hermite; one node if sigma = 0).
struct GaussNodes {
  int n = 1;
  std::array<double, 9> offset_V{};
  std::array<double, 9> weight{};
};
GaussNodes gauss_nodes(double sigma_V);

struct Classification {
  DemodDetect detect = DemodDetect::BelowThreshold;
  PixelDecision peak;               // pixel at the spot centre (profile 1)
  PixelDecision background;         // pixel with background only
  double row_false_activation = 0;  // P(some pixel of the row activates on background alone)
};
Classification classify(const LsDemodulationConfig& cfg, double signal_A, double background_A);

}  // namespace rangesim::golden
