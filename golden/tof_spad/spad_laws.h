#pragma once
// One free-running SPAD between two TDC armings, on the TDC's phase bins (golden/tof_spad/
// dead_time_chain.h puts the group together). A SPAD is unaffected by the TDC: Poisson arrivals
// of mean r_i in bin i (periodic over the laser period), each arrival while live an avalanche,
// then dead for `dead_bins` bins (non-paralysable). Its state at a time is fully described by
// when it recharges (live now, or live again d bins from now), so its law at a TDC arming is a
// vector over d: the Markov state of the renewal chain.
//
// Time is counted in the TDC's actual bins (INL/DNL edges). The dead time is a whole number of
// bins; an avalanche in bin b leaves the SPAD live again at the same point of bin b + dead_bins
// (exact when the dead time is a whole number of laser periods, as in the preset, or of bins of a
// linear TDC). Where in its bin it recharges is not followed: a recharging SPAD counts as live for
// half of that bin (fires with 1 - exp(-r/2)), which makes the scheme second order in the bin
// width (the avalanche point is near uniform in the bin; the error is O((r_i)^2) per recharge).
#include <vector>

namespace rangesim::golden::spad {

// A SPAD's law at a reference bin (a TDC arming): live (since some time) with probability `live`,
// or recharging during bin d after the reference with probability ret[d] (0 <= d < dead bins).
struct SpadLaw {
  double live = 0;
  std::vector<double> ret;
  double dead() const;  // sum of ret: not live at the reference
};

// Per-bin firing probabilities of one SPAD over one period: q[i] = 1 - exp(-r_i) when live for
// the whole bin, qh[i] = 1 - exp(-r_i / 2) in the bin where it recharges.
struct FiringProbs {
  std::vector<double> q, qh;
  int phase_bins() const { return static_cast<int>(q.size()); }
};
FiringProbs firing_probs(const std::vector<double>& arrivals_per_bin);

// The same probabilities with every bin at the period's mean rate (the phase-free pool,
// dead_time_chain.cpp).
FiringProbs flat_firing_probs(const std::vector<double>& arrivals_per_bin);

// Free run from absolute bin `from` to absolute bin `arm` (>= from; bin b has the probabilities
// of phase b mod Np): `live_mass` is live from bin `from` on, recharge[j] recharges during bin
// from + j (half live there, j < dead bins). Returns the law at `arm`. Work: O(arm - from + dead).
SpadLaw free_run(const FiringProbs& fp, int dead_bins, long long from, double live_mass,
                 const std::vector<double>& recharge, long long arm);
// The same into `live` and ret[0 .. dead_bins) with a scratch ring of dead_bins (no allocation).
void free_run_into(const FiringProbs& fp, int dead_bins, long long from, double live_mass, const double* recharge,
                   int recharges, long long arm, double* ring, double& live, double* ret);

}  // namespace rangesim::golden::spad
