#pragma once
// The SPAD's timing jitter, in the order of the physics. A SPAD fires on the first photon it
// absorbs while live, by the photon's true arrival time (the pulse's width alone); its avalanche's
// timestamp carries the jitter; the TDC takes the group's first *recorded* avalanche. The
// event-level kernel does exactly this (systemc/tof_spad/pixel_kernel.cpp, sensor_kernel.cpp).
//
// So a live SPAD's first avalanche of a period has, in recorded time, the law of its first photon
// (true time: intensity lambda(t) times the survival exp(-Lambda(t))) convolved with the jitter,
// and the chain (dead_time_chain.h, pile_up.h), which takes each SPAD's firing per bin as a
// hazard, gets the hazard of that law: r_j = ln(S_j / S_{j+1}), S_j = P(no avalanche recorded
// before bin j). Folding the jitter into the arrivals instead (the first *jittered* photon fires)
// makes a SPAD with two photons in a pulse fire early: at 1 Mcounts/s (0.025 photons per SPAD
// and pulse) golden's accuracy was 1.8 % (26 um) below the kernel's at 3.6 m.
//
// Where: in a window around the echoes, from a SPAD live at the window's start (two jitter
// reaches before the echo's); elsewhere the arrivals are uniform and a jittered Poisson process
// is the same process. A window longer than a period (jitter or pulse of a period) falls back to
// the jitter folded into the pulse's width.
//
// Approximations: a SPAD that recharges inside the echo sees the rest of it through the hazard
// (its first-photon law restarts at the recharge); a SPAD's dead time runs from its recorded time
// (a fraction of a bin against dead times of hundreds of bins; it shows on the recharge onto a
// strong echo: 1.5 ps at 10 Mcounts/s, SpadGolden.EstimatorMomentsCoatesStrongEcho); inside a bin
// without echo the first photon is taken uniform.
#include "golden/tof_spad/arrival_rates.h"
#include "golden/tof_spad/tdc_bins.h"

namespace rangesim::golden::spad {

// Per phase bin and laser cycle: the hazard of a live SPAD's first recorded avalanche (`total`)
// and the echo's part of it (`signal`, the share of first photons from the echo). Without jitter
// it is bin_arrivals(bins, a).
BinArrivals recorded_arrivals(const TdcBins& bins, const Arrivals& a);

}  // namespace rangesim::golden::spad
