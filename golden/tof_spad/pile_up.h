#pragma once
// First-photon pile-up with dead time carried across laser cycles: the expected TDC histogram in
// closed form (the first-photon histogram of a SPAD; Coates, "The correction for photon pile-up in the measurement of
// radiative lifetimes", 1968), completing thesis eq. 2.32-2.33 where it stops ("P_n(t; s(t)) is still under
// analysing").
//
// Per laser cycle the TDC is stopped by the first detection among the columns that share it.
// With r_i our pixel's mean detections in bin i and s = 1 + (columns_per_tdc - 1) x
// neighbour_rate_fraction the TDC sees s r_i (neighbours with our time profile), detects in bin i
// with hazard q_i = 1 - exp(-s r_i) if still armed, and the hit is ours with probability 1 / s.
// After a recorded hit the TDC group is blind for max(dead time, busy time); if that reaches past
// the end of the period the next cycles are blind and the first live cycle is armed only from
// phase bin v = (i + block) mod Np on. The arming phase is a Markov chain over cycles; its
// stationary law gives the histogram per physical cycle. See docs/tof-spad.md for the derivation.
// This chain has no memory in the SPADs: it is exact without SPAD dead time; with dead time the
// golden model uses the renewal chain (dead_time_chain.h, which this chain starts) and falls back
// to this one on the mean-field rates only where that chain does not run.
#include <vector>

namespace rangesim::golden::spad {

struct PileUpInput {
  std::vector<double> photons_per_bin;  // r_i of our pixel for the Np phase bins of a period
  int codes = 0;                        // bins < codes hold a TDC event; later ones overflow
  double share = 1;                     // s >= 1: TDC-group rate / our rate
  int block_event_bins = 0;             // blind phase bins after a recorded event (>= 0)
  int block_overflow_bins = 0;          // blind phase bins after an overflow hit (SPAD dead time only)
};

struct PileUpHistogram {
  std::vector<double> event_prob;             // our pixel's P(event in code i) per physical cycle, i < codes
  std::vector<double> background_event_prob;  // the part of event_prob from background and dark counts (may be empty)
  std::vector<double> armed_prob;             // P(TDC group armed at the start of phase bin i) per physical cycle
  std::vector<double> hazard;                 // q_i = 1 - exp(-s r_i): group detection probability when armed
  double share = 1;                           // s
  double cycles_per_live_cycle = 1;           // mean cycles from one armed cycle start to the next (>= 1)
  double group_events_per_cycle = 0;          // recorded TDC events per physical cycle (all sharing columns)
  double our_events_per_cycle = 0;            // of which ours
  int iterations = 0;                         // power iterations of the arming-phase chain
  bool converged = false;
  const char* model = "TDC blocking, no SPAD dead time";  // which model made it (dead_time_chain.h)
};

// The stationary arming-phase chain by power iteration, O(Np) per iteration: the probability of
// reaching bin i armed from arming phase u is exp(-(R_i - R_u)) with R the cumulative group rate,
// so all starting phases are carried in one running survival sum (never exp(+R): no overflow,
// underflow goes to the right limit 0).
PileUpHistogram expected_histogram(const PileUpInput& in);

// Shared-TDC rate factor s = 1 + (columns_per_tdc - 1) x neighbour_rate_fraction.
double tdc_share(int columns_per_tdc, double neighbour_rate_fraction);

}  // namespace rangesim::golden::spad
