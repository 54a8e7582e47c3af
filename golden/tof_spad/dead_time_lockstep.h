#pragma once
// The armed windows of the usual group (one class: every column sees our rates; each arming phase
// armed from one hit bin) for all arming phases at once, bin by bin in lockstep: the same sums as
// chain::armed_window, with the phases in the inner loop so that the compiler can vectorise it.
// This is the chain's hot loop on the preset (golden/tof_spad/dead_time_chain.h).
#include "golden/tof_spad/dead_time_window.h"

namespace rangesim::golden::spad::chain {

// Whether the lockstep pass applies, and if so the laws transposed by arming phase
// (table[t * np + phi]).
struct Lockstep {
  bool on = false;
  std::vector<int> hit_of_phase;  // the hit bin that arms at each phase
  Vec winner_t, fresh_t;
  Vec arm_offset;                                        // Setup::arm_offset as doubles
  Vec winner_live, winner_dead, fresh_live, fresh_dead;  // by hit bin
  void build(const Setup& su);
};

// One pass: every arming phase phi weighted pi[phi] (one class: the last winner is of it).
void lockstep_pass(const Setup& su, const Lockstep& ls, const ArmState& st, const Vec& pi, Book& b, PoolBook& pool,
                   Vec& scratch);

}  // namespace rangesim::golden::spad::chain
