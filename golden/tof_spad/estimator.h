#pragma once
// The range estimator on the TDC histogram (thesis eq. 2.34 / 4.19, with the correct
// normalisation sum(h_i t_i) / sum(h_i)): peak bin, window PW around it, optional Coates pile-up
// correction and background subtraction, centroid. Two forms of the same estimator:
// - estimate_time_s: applied to one measured (or simulated) histogram;
// - estimator_moments: its bias and variance in closed form from the expected histogram.
#include <optional>
#include <vector>

#include "golden/tof_spad/pile_up.h"
#include "golden/tof_spad/tdc_bins.h"

namespace rangesim::golden::spad {

struct EstimatorConfig {
  int peak_window_bins = 7;         // PW
  bool coates = true;               // Coates correction before the centroid
  bool subtract_background = true;  // subtract the mean per-bin level of the bins outside PW
};

// Codes [lo, hi] of the window: PW bins with the peak in the middle (for an even PW one more bin
// before the peak), shifted to stay inside [0, codes).
struct Window {
  int lo = 0, hi = -1;
};
Window peak_window(int peak_bin, int peak_window_bins, int codes);

// One histogram as the readout sees it.
struct HistogramCounts {
  std::vector<double> events;  // our pixel's events per code
  std::vector<double> armed;   // cycles in which the TDC group was armed at the start of each code
  double share = 1;            // s: TDC-group rate / ours (the arbitration share, from the preset)
};

// Coates (dead-time aware, shared TDC): r_i = -ln(1 - s h_i / A_i) / s with A_i the armed
// cycles of code i (known from the TDC's own event log; for a free-running-free TDC with no
// carry-over A_i = N - sum_{j<i} H_j, the textbook form). A bin that stopped every armed cycle is
// capped at q = 1 - 1 / (2 A_i). Returns our pixel's estimated mean detections per cycle.
std::vector<double> coates_rates(const HistogramCounts& h);
void coates_rates(const HistogramCounts& h, std::vector<double>& out);  // the same into out (its capacity kept)

// The code the estimator centres its window on: the maximum of the Coates rates (or of the raw
// events without the correction).
int peak_bin(const HistogramCounts& h, const EstimatorConfig& cfg);

// The estimator on one histogram: the round-trip time in s, or nothing when nothing is
// detected (no events, or no counts above the background in the window).
// peak_bin_out (if given) receives the code the window was centred on (peak_bin), for
// peak_significance: the same code without the Coates rates made twice per pixel.
std::optional<double> estimate_time_s(const HistogramCounts& h, const TdcBins& bins, const EstimatorConfig& cfg,
                                      int* peak_bin_out = nullptr);

// Closed-form moments of estimate_time_s for a histogram of `cycles` cycles with the expected
// per-cycle law `h`, the peak taken at `peak_bin` (the detection criterion makes sure the peak
// search finds the echo). Delta method on the ratio of the two linear sums: mean to second
// order, variance to first. Raw counts: multinomial covariance N (p_i delta_ij - p_i p_j).
// Coates: each r_i is a hazard estimate; hazard estimates of different bins are uncorrelated
// (martingale increments), Var = q (1 - q/s) / (s A (1 - q)^2), bias = s Var / 2 (log's curvature).
struct EstimateMoments {
  int peak_bin = -1;
  Window window;
  bool defined = false;  // expected window sum above the background > 0
  double mean_s = 0;     // E[estimate]
  double var_s2 = 0;     // Var[estimate]
};
EstimateMoments estimator_moments(const PileUpHistogram& h, const TdcBins& bins, double cycles, int peak_bin,
                                  const EstimatorConfig& cfg);

// Thompson, Larson and Webb, "Precise nanometer localization analysis for individual fluorescent probes" (Biophys. J.,
// 2002), one dimension: timing sigma of an ideal localisation from N signal photons, IRF sigma s, bin width a and b
// background counts per bin.
double thompson_sigma_t_s(double irf_sigma_s, double bin_s, double signal_counts, double background_per_bin);

}  // namespace rangesim::golden::spad
