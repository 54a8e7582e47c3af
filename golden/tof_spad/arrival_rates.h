#pragma once
// Mean photon detections per TDC bin and laser cycle, before pile-up: the inhomogeneous Poisson
// intensity of thesis eq. 2.31 (Gaussian echo) plus the uniform background and dark counts of
// eq. 2.27, integrated over the actual bin edges.
#include <vector>

#include "core/tof_spad/config.h"
#include "golden/tof_spad/tdc_bins.h"

namespace rangesim::golden::spad {

struct Arrivals {
  double signal_per_cycle = 0;  // mean signal detections per laser cycle (signal rate / repetition rate)
  double round_trip_s = 0;      // echo centre 2 L / c
  double irf_sigma_s = 0;       // laser pulse sigma and SPAD jitter in quadrature
  double uniform_rate_Hz = 0;   // background + dark count rate, uniform over the cycle
  double live_fraction = 1;     // free-running SPAD live fraction 1 / (1 + m tau_dead), m = S + B + D
};

// IRF sigma: sigma_per_fwhm x FWHM of the pulse, combined with the jitter in quadrature.
double irf_sigma_s(const TofSpadConfig& cfg);

// Operating point -> arrivals. Rates are PDE-weighted count rates (preset header).
Arrivals make_arrivals(const TofSpadConfig& cfg, double signal_Hz, double background_Hz, double distance_m);

// r_i for the Np phase bins of one period, times the live fraction: the SPAD keeps firing (and
// going dead) while the TDC is stopped or busy, so at a random time it is live with the
// non-paralysable probability 1 / (1 + m tau_dead) (the non-paralysable dead-time model, n = m / (1 + m tau)). This
// stationary factor is the thesis's eq. 2.29-2.30 limit (detections <= 1 / t_dead) done properly;
// its time correlation with the TDC's blocking is neglected (docs/tof-spad.md). The echo is integrated with erfc only
// within
// +-12 sigma of its centre (beyond, < 1e-32 of it); echoes are assumed inside the period.
std::vector<double> photons_per_bin(const TdcBins& bins, const Arrivals& a);

}  // namespace rangesim::golden::spad
