#pragma once
// The TDC group's expected histogram with the SPADs' dead time followed exactly through the
// TDC's blocking: a renewal (Markov) chain on the TDC's armings (golden/tof_spad/pile_up.h keeps
// the chain without SPAD dead time, which this reduces to).
//
// Why a chain on armings: the SPADs free-run, unaffected by the TDC; the TDC is armed at a bin
// start A, takes the first avalanche among its columns (hit H) and re-arms at the start of H's bin
// + block (or at the next START). Given the SPADs' states at A, the group's first avalanche and
// every SPAD's state at the next arming follow by free-running each SPAD (golden/tof_spad/
// spad_laws.h): while armed, a SPAD fires only as the hit (so a SPAD live at some time after A
// stays live until it fires), the winner is dead from H and free-runs from H + dead, a loser that
// was live at H is a fresh SPAD from H on, a loser still dead at H carries its recharge time over.
// The SPADs are independent and the event "first avalanche at H by w" is a product over SPADs, so
// given the armings' history the SPADs stay independent. State of the chain: the arming phase
// with the law of the last winner (exact: it is fresh from its avalanche) and of the losers.
//
// The approximations: (1) "product form": the losers' laws at an arming are taken independent of
// each other given the arming phase and the previous winner's class. The laws of losers that
// were live at the last hit (all of them at low rates) are exact; the laws of losers still dead at
// the hit (most of them at count rates >> 1 / dead time) are pooled over the arming phases
// (their phase dependence comes from the echo, a small part of the rate there). Exact for one or
// two columns per TDC. (2) The avalanche takes the echo's jittered time (the IRF) also for its
// dead time, which really runs from the unjittered one. (3) A whole number of bins of dead time
// (spad_laws.h). Against the event-level kernel at 1 MHz signal, 1 kHz to 1 GHz background, four
// columns, the preset: detections per cycle within 0.11 %, the armed fraction within 0.08 % up to
// 100 MHz and 0.39 % at 1 GHz (where (1) and (2) each give about -0.2 %: the armed fraction is
// 2 % there), tests/systemc/tof_spad/test_spad_deadtime_validation.cpp, docs/tof-spad.md.
#include <vector>

#include "golden/tof_spad/pile_up.h"

namespace rangesim::golden::spad {

// SPADs of the group with the same arrivals.
struct SpadClassArrivals {
  int count = 1;                        // SPADs of this class sharing the TDC
  std::vector<double> arrivals;         // mean photon + dark arrivals per phase bin and laser cycle
  std::vector<double> signal_arrivals;  // of which echo photons (the rest is background and dark counts)
};

struct DeadTimeChainInput {
  std::vector<SpadClassArrivals> classes;  // classes[0] holds our pixel: 1 / classes[0].count of its events are ours
  int codes = 0;                           // bins < codes hold a TDC event; later ones overflow
  int dead_bins = 1;                       // SPAD dead time in phase bins (>= 1)
  int block_event_bins = 0;                // TDC blind bins after an event
  int block_overflow_bins = 0;             // after an overflow hit
  double share = 1;                        // reported as PileUpHistogram::share
};

// The chain's work in bin steps per iteration (phase bins x (dead + longest free run)); above
// kDeadTimeChainMaxWork SpadModel uses the mean-field chain instead (dead times or busy times of
// many periods) and says so.
long long dead_time_chain_work(const DeadTimeChainInput& in);
constexpr long long kDeadTimeChainMaxWork = 8LL << 20;

// The stationary histogram per physical laser cycle. Classes with count 0 are ignored.
PileUpHistogram dead_time_histogram(const DeadTimeChainInput& in);

}  // namespace rangesim::golden::spad
