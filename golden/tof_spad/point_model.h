#pragma once
// One operating point of the tof-spad golden model: signal and background count rates and a
// target distance -> expected histogram -> detection verdict, bias and spread of the range.
// Data flow: arrival_rates -> timing_jitter -> pile_up (dead_time_chain) -> estimator -> (this) -> evaluate.cpp.
#include <string>
#include <vector>

#include "core/tof_spad/config.h"
#include "golden/tof_spad/arrival_rates.h"
#include "golden/tof_spad/dead_time_chain.h"
#include "golden/tof_spad/estimator.h"
#include "golden/tof_spad/pile_up.h"
#include "golden/tof_spad/tdc_bins.h"

namespace rangesim::golden::spad {

struct PointResult {
  std::string detect;               // "detectable" or a reason id (SpadModel::reasons())
  double bias_m = 0;                // E[L_hat] - L (TDC nonlinearity, truncation, pile-up, ratio bias)
  double std_m = 0;                 // sqrt(Var[L_hat])
  double accuracy_m = 0;            // sqrt(bias^2 + std^2)
  double signal_counts = 0;         // expected signal events of our pixel in the peak window
  double background_counts = 0;     // expected background + dark events in the peak window
  double detections_per_cycle = 0;  // our pixel's recorded TDC events per laser cycle
  double armed_at_echo = 0;         // fraction of cycles with the TDC still armed at the window start
  double background_per_bin = 0;    // expected background events per bin at the echo (Thompson's b)
  double cycles = 0;                // laser cycles in the histogram
  EstimateMoments moments;
  bool chain_converged = true;
};

class SpadModel {
 public:
  explicit SpadModel(const TofSpadConfig& cfg);

  // With the preset's estimator (histogram.coates_correction, histogram.subtract_background).
  // With a fixed pattern (fixed_pattern.prnu_fraction, fixed_pattern.dsnu_rms_Hz) the accuracy is
  // the rms over the chip's pixels (evaluate_chip); the rest is the mean pixel's.
  PointResult evaluate(double signal_Hz, double background_Hz, double distance_m) const;
  PointResult evaluate(double signal_Hz, double background_Hz, double distance_m, const EstimatorConfig& est) const;

  // One pixel of a chip: its photon detection efficiency relative to the mean (PRNU: scales its
  // signal and background rates) and its dark count rate's offset (DSNU); the columns sharing its
  // TDC at the mean.
  struct PixelDraw {
    double gain = 1, dark_extra_Hz = 0;
  };
  PointResult evaluate_pixel(double signal_Hz, double background_Hz, double distance_m, const EstimatorConfig& est,
                             const PixelDraw& draw) const;

  // A pixel that receives several returns (a depth step inside the lens's point spread or the
  // pixels' crosstalk; multipath): their histograms add, the estimate is that of the sum (a flying
  // pixel: between the returns' ranges, weighted by their counts). Every column of the group sees
  // the same; the bias is against `truth_m`, the first return's TDC code is the echo's.
  struct SignalReturn {
    double signal_Hz = 0, distance_m = 0;
  };
  PointResult evaluate_returns(const std::vector<SignalReturn>& returns, double background_Hz, double truth_m) const;

  // Expected per-cycle histogram of an operating point: the renewal chain of the SPADs' dead
  // time (dead_time_chain.h); without dead time, or with dead and busy times too long for the
  // chain, the TDC's chain alone on the mean-field rates (PileUpHistogram::model says which).
  // Both on the SPADs' recorded avalanche times (timing_jitter.h: first photon by true arrival,
  // then the jitter).
  PileUpHistogram histogram(double signal_Hz, double background_Hz, double distance_m) const;
  PileUpHistogram histogram(const Arrivals& a) const;
  // Our pixel with arrivals `ours`, the sharing columns with `others` (times the neighbour fraction).
  PileUpHistogram histogram(const Arrivals& ours, const Arrivals& others) const;
  // The TDC's blocking in bins (and the mean-field input of its chain).
  PileUpInput pile_up_input(std::vector<double> photons_per_bin) const;
  // The group of the renewal chain: our pixel, and the sharing neighbours at
  // tdc.neighbour_rate_fraction of `others` (one class with ours when they are equal).
  DeadTimeChainInput chain_input(const BinArrivals& ours, const BinArrivals& others) const;
  int dead_bins() const;  // SPAD dead time in phase bins (rounded)

  // The point's model on given arrivals (ours and the sharing columns'), bias against the round trip.
  PointResult evaluate_arrivals(const Arrivals& ours, const Arrivals& others, const EstimatorConfig& est,
                                double truth_round_trip_s) const;

  const TofSpadConfig& config() const { return cfg_; }
  const TdcBins& bins() const { return bins_; }
  EstimatorConfig estimator() const;
  double cycles() const { return cycles_; }  // integration_time x repetition rate x frames averaged
  double share() const { return share_; }

  // Reason ids with one-line descriptions, "detectable" first.
  static std::vector<std::pair<std::string, std::string>> reasons();

 private:
  TofSpadConfig cfg_;
  TdcBins bins_;
  double cycles_ = 0;
  double share_ = 1;
};

// Upper bound of the afterpulse events per recorded event that can reach an armed TDC: an
// afterpulse comes dead_time + Exp(tau_ap) after the avalanche; the TDC group is blind for
// max(dead, busy), so at most p_ap exp(-(block - dead) / tau_ap) of them land while it is armed.
double afterpulse_armed_fraction(const TofSpadConfig& cfg);

}  // namespace rangesim::golden::spad
