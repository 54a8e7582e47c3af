#pragma once
// Mean photon detections per TDC bin and laser cycle, before pile-up: the inhomogeneous Poisson
// intensity of thesis eq. 2.31 (Gaussian echo) plus the uniform background and dark counts of
// eq. 2.27, integrated over the actual bin edges.
#include <vector>

#include "core/tof_spad/config.h"
#include "golden/tof_spad/tdc_bins.h"

namespace rangesim::golden::spad {

// A further return of the pulse (multipath; a neighbour's surface through the point spread).
struct Return {
  double signal_per_cycle = 0;
  double round_trip_s = 0;
};

struct Arrivals {
  double signal_per_cycle = 0;  // mean signal detections per laser cycle (signal rate / repetition rate)
  double round_trip_s = 0;      // echo centre 2 L / c
  std::vector<Return> returns;  // further echoes, the same pulse shape
  double pulse_sigma_s = 0;     // echo photons' arrival spread: the laser pulse's sigma (no jitter)
  double jitter_sigma_s = 0;    // SPAD timing jitter: on the recorded avalanche time only (timing_jitter.h)
  double uniform_rate_Hz = 0;   // background + dark count rate, uniform over the cycle
  double live_fraction = 1;     // free-running SPAD live fraction 1 / (1 + m tau_dead), m = S + B + D (mean field only)
};

// IRF sigma of the recorded histogram without pile-up: sigma_per_fwhm x FWHM of the pulse,
// combined with the jitter in quadrature. The arrivals carry the pulse alone: a SPAD fires on its
// first photon by the photon's true arrival time and only the avalanche's timestamp has the jitter.
double irf_sigma_s(const TofSpadConfig& cfg);

// Operating point -> arrivals. Rates are PDE-weighted count rates (preset header). With
// multipath.* on, every echo has its second return.
Arrivals make_arrivals(const TofSpadConfig& cfg, double signal_Hz, double background_Hz, double distance_m);

// Mean arrivals per phase bin and laser cycle before any dead time, by true arrival time (the
// pulse's width, no jitter): all of them (echo, background and dark counts) and the echo's part. The echo is integrated
// with erfc only within
// +-12 sigma of its centre (beyond, < 1e-32 of it); echoes are assumed inside the period.
struct BinArrivals {
  std::vector<double> total, signal;
};
BinArrivals bin_arrivals(const TdcBins& bins, const Arrivals& a);

// The mean-field input of the chain without SPAD dead time (pile_up.h): r_i = total_i times the
// stationary live fraction 1 / (1 + m tau_dead) of a free-running non-paralysable SPAD (thesis
// eq. 2.29-2.30 done properly). Its time correlation with the TDC's blocking is neglected; the
// golden model uses it only where the renewal chain (dead_time_chain.h) does not run: no dead
// time (where it is exact) or dead and busy times too long for the chain.
std::vector<double> photons_per_bin(const TdcBins& bins, const Arrivals& a);

}  // namespace rangesim::golden::spad
