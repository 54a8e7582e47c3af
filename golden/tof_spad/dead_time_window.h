#pragma once
// The armed window of the renewal chain (golden/tof_spad/dead_time_chain.h): from a TDC arming to
// the hit, bin by bin, the group's survival, the hit, which class takes it and every SPAD's state
// then (a loser live at the hit, one that fired in the hit's bin, one still recharging).
#include <array>
#include <cstddef>
#include <vector>

#include "golden/tof_spad/dead_time_chain.h"
#include "golden/tof_spad/spad_laws.h"

namespace rangesim::golden::spad::chain {

using Vec = std::vector<double>;

// Laws of one class at each of n hit bins, flat: live[i], ret[i * dead + d], with their dead mass.
struct LawTable {
  int dead = 0;
  Vec live, ret, dead_total;
  void reset(int n, int dead_bins);         // keeps the storage (the chain runs once per operating point)
  void reset_totals(int n, int dead_bins);  // live and dead masses only (the lockstep pass keeps the laws)
  const double* ret_of(int i) const {
    return ret.empty() ? nullptr : ret.data() + static_cast<std::size_t>(i) * static_cast<std::size_t>(dead);
  }
  double* ret_of(int i) { return ret.data() + static_cast<std::size_t>(i) * static_cast<std::size_t>(dead); }
  void finish(int i);  // dead_total[i] from ret
};

// The chain's fixed parts: per class the firing probabilities, per hit bin the next arming and
// the laws there of the hit's winner and of a loser that was live at the hit.
struct Setup {
  int np = 0, codes = 0, dead = 0, nc = 0;
  std::vector<int> count;
  std::vector<FiringProbs> fp, flat;
  Vec background_fraction;                       // of our pixel's arrivals, per bin
  std::vector<long long> arm_offset;             // bins from a hit bin's start to the next arming
  std::vector<int> arm_phase;                    // phase bin of that arming
  std::vector<std::vector<int>> hits_arming_at;  // [arming phase]: the hit bins that arm there
  std::vector<LawTable> winner, fresh;           // [class], by hit bin
  // Every SPAD live (after a dead time without a hit): per bin P(no SPAD fires), per class the
  // effective rate; over a whole period P(no hit) = 1 - one_minus_q.
  Vec silent;
  std::vector<Vec> rate;
  double one_minus_q = 0;
  Vec tail_transition;  // [start bin * np + arming phase]: where such a window's hit arms the TDC
};
// Fills `s` (reusing its storage) from the input, all but the laws of the hit bins.
void build_setup(const DeadTimeChainInput& in, Setup& s);
// The winner's and the fresh loser's law at the next arming for every hit bin (armed_window's).
void build_law_tables(Setup& s);

// A SPAD's law at an arming as a mixture of stored laws (the chain is linear in the weights).
struct LawPart {
  enum Source { kWinner, kFresh, kPool };
  const double* ret = nullptr;
  double live = 0, dead = 0, w = 0;
  Source src = kWinner;  // which stored law: Setup::winner or fresh (of a hit bin), or the pool
};
using LawMix = std::vector<LawPart>;

// The chain's state at each arming phase: P(the last winner was of class c) and the laws.
struct ArmState {
  std::vector<Vec> omega;                 // [class][phase]
  std::vector<std::vector<LawMix>> win;   // [class][phase]: the last winner, if of class c
  std::vector<std::vector<LawMix>> lose;  // [class][phase]: a loser of class c
  std::vector<SpadLaw> pool;              // [class]: a loser that was still dead at the hit
};

// What the armed windows add up, weighted by P(arming phase, last winner class) (the chain's
// stationary law of the arming phase from the previous pass), and the transition matrix.
struct Book {
  int np = 0;
  std::vector<Vec> wins, fresh, fired, dead;  // [class][hit bin]: the hit's winner and its losers by state
  Vec group, ours, ours_background, armed;    // [bin]
  double length = 0;                          // bins from an arming to the next
  double armed_cycles = 0;                    // laser cycles with armed time per arming
  double hit_offset = 0;                      // bins from a hit bin to the next arming
  Vec transition;                             // [phi * np + next arming phase], per arming at phi
  Vec tail_mass, tail_row;                    // [phi]: P(no hit in the dead bins), weighted as the book / the row
  void reset(int np_, int nc);
};

// The losers still recharging at the hit, for the pooled law: P(the others hit in bin t of the
// window while this SPAD is still dead), and the recharge laws, weighted by P(arming phase).
struct PoolBook {
  std::vector<std::array<Vec, 2>> weight;   // [class][last winner, loser][t]
  std::vector<std::array<Vec, 2>> law_sum;  // [class][kind][d]
  std::vector<std::array<double, 2>> law_weight;
  bool track = true;  // sum the laws (off while no loser is still dead at a hit)
  void reset(int nc, int dead);
};

// The window armed at phase `phi` whose last winner was of class `cw` (probability omega given
// phi): `weight` = P(arming at phi, last winner cw) weighs the books, omega the transition row.
// `scratch` holds dead bins per kind (the mixed laws).
void armed_window(const Setup& su, const ArmState& st, int phi, int cw, double omega, double weight, Book& book,
                  PoolBook& pool, Vec& scratch);

// The windows' tails (every SPAD live: the group memoryless) of all armings at once, added to
// the book and the transitions: call once after all armed_window calls of a pass.
void add_tails(const Setup& su, Book& book);

}  // namespace rangesim::golden::spad::chain
