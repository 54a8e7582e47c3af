#include "golden/tof_spad/dead_time_chain.h"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "golden/tof_spad/dead_time_lockstep.h"
#include "golden/tof_spad/dead_time_window.h"
#include "golden/tof_spad/spad_laws.h"

namespace rangesim::golden::spad {

namespace {

using chain::ArmState;
using chain::Book;
using chain::LawMix;
using chain::LawPart;
using chain::LawTable;
using chain::PoolBook;
using chain::Setup;
using chain::Vec;

size_t u(long long i) { return static_cast<size_t>(i); }

// The law of a loser still dead at the hit, pooled over the armings: the averaged "others hit in
// bin t" weights times the averaged recharge laws, free-run at the period's mean rate from the hit
// bin to the next arming (hit_offset bins on average).
SpadLaw pooled_law(const Setup& su, const PoolBook& pool, int c, double hit_offset) {
  Vec recharge(u(su.dead) - 1, 0.0);  // recharge[j - 1]: recharging j bins after the hit bin's start
  for (int kind = 0; kind < 2; ++kind) {
    const double lw = pool.law_weight[u(c)][u(kind)];
    if (!(lw > 0)) continue;
    const Vec& y = pool.weight[u(c)][u(kind)];
    const Vec& law = pool.law_sum[u(c)][u(kind)];
    for (int t = 0; t < su.dead; ++t) {
      if (!(y[u(t)] > 0)) continue;
      const double yt = y[u(t)] / lw;
      for (int j = 1; t + j < su.dead; ++j) recharge[u(j) - 1] += yt * law[u(t + j)];
    }
  }
  double total = 0;
  for (double x : recharge) total += x;
  if (!(total > 0)) {
    SpadLaw live;
    live.live = 1, live.ret.assign(u(su.dead), 0.0);
    return live;
  }
  for (double& x : recharge) x /= total;
  return free_run(su.flat[u(c)], su.dead, 1, 0.0, recharge, std::max(1LL, std::llround(hit_offset)));
}

// The arming state from the last pass: the laws are mixtures of the stored ones, linear in the
// pass's weights.
void update_state(const Setup& su, const Book& b, const PoolBook& pool, ArmState& st, bool new_pool = true) {
  if (new_pool)
    for (int c = 0; c < su.nc; ++c) st.pool[u(c)] = pooled_law(su, pool, c, b.hit_offset);
  for (int phi = 0; phi < su.np; ++phi) {
    const auto& from = su.hits_arming_at[u(phi)];
    double all_wins = 0;
    for (int c = 0; c < su.nc; ++c)
      for (int h : from) all_wins += b.wins[u(c)][u(h)];
    if (!(all_wins > 0)) continue;  // never reached: keep the previous state
    for (int c = 0; c < su.nc; ++c) {
      double wins = 0, losers = 0;
      for (int h : from)
        wins += b.wins[u(c)][u(h)], losers += b.fresh[u(c)][u(h)] + b.fired[u(c)][u(h)] + b.dead[u(c)][u(h)];
      st.omega[u(c)][u(phi)] = wins / all_wins;
      const LawTable& w = su.winner[u(c)];
      const LawTable& f = su.fresh[u(c)];
      const auto part = [](const LawTable& t, int h, double weight, LawPart::Source src) {
        return LawPart{t.ret_of(h), t.live[u(h)], t.dead_total[u(h)], weight, src};
      };
      if (wins > 0) {
        LawMix& win = st.win[u(c)][u(phi)];
        win.clear();
        for (int h : from)
          if (b.wins[u(c)][u(h)] > 0) win.push_back(part(w, h, b.wins[u(c)][u(h)] / wins, LawPart::kWinner));
      }
      if (losers > 0) {
        LawMix& lose = st.lose[u(c)][u(phi)];
        lose.clear();
        double dead = 0;
        for (int h : from) {
          if (b.fresh[u(c)][u(h)] > 0) lose.push_back(part(f, h, b.fresh[u(c)][u(h)] / losers, LawPart::kFresh));
          if (b.fired[u(c)][u(h)] > 0) lose.push_back(part(w, h, b.fired[u(c)][u(h)] / losers, LawPart::kWinner));
          dead += b.dead[u(c)][u(h)];
        }
        const SpadLaw& p = st.pool[u(c)];
        if (dead > 0) lose.push_back({p.ret.data(), p.live, p.dead(), dead / losers, LawPart::kPool});
      }
    }
  }
}

// Stationary law of the arming phase by power iteration from `pi` (the last pass's), a bounded
// number of steps per pass: the passes refine it further. Damped after the first steps (a
// blocking of whole periods can make the chain nearly periodic).
void stationary(const Vec& tr, Vec& pi) {
  const size_t n = pi.size();
  Vec next(n);
  // A matrix step costs n^2: fewer steps for long periods (the passes continue them).
  const int steps = static_cast<int>(std::clamp(2e7 / (static_cast<double>(n) * static_cast<double>(n)), 5.0, 60.0));
  for (int it = 0; it < steps; ++it) {
    std::fill(next.begin(), next.end(), 0.0);
    for (size_t i = 0; i < n; ++i)
      if (pi[i] > 0)
        for (size_t j = 0; j < n; ++j) next[j] += pi[i] * tr[i * n + j];
    double z = 0;
    for (double x : next) z += x;
    if (!(z > 0)) return;
    const double keep = it >= steps / 3 ? 0.5 : 0.0;
    double diff = 0;
    for (size_t j = 0; j < n; ++j) {
      const double v = keep * pi[j] + (1 - keep) * next[j] / z;
      diff += std::fabs(v - pi[j]);
      pi[j] = v;
    }
    if (diff < 1e-14) return;
  }
}

const char* const kModel = "renewal chain of the SPADs' dead time";
// Relative change of the detections and the armed fraction (and L1 change of the arming law)
// between passes at which the chain is taken as converged: far below the model's own error.
constexpr double kTolerance = 1e-8;
// Passes before giving up (PileUpHistogram::converged false; evaluate counts such points): the
// preset needs 2-15, 1 GHz of background ~350 (the losers' pooled law mixes slowly there); and a
// bound on the whole chain's work (bin steps), for long periods and dead times.
constexpr int kMaxPasses = 600;
constexpr double kWorkBudget = 3e9;

PileUpHistogram finish(const Setup& su, const Book& b, double share) {
  PileUpHistogram h;
  h.share = share;
  h.model = kModel;
  const double per_cycle = su.np / b.length;  // armings per laser cycle
  h.cycles_per_live_cycle = b.length / su.np / b.armed_cycles;
  h.event_prob.resize(u(su.codes));
  h.background_event_prob.resize(u(su.codes));
  h.armed_prob.resize(u(su.np));
  h.hazard.resize(u(su.np));
  for (int i = 0; i < su.np; ++i) {
    h.armed_prob[u(i)] = std::min(1.0, b.armed[u(i)] * per_cycle);
    h.hazard[u(i)] = b.armed[u(i)] > 0 ? std::clamp(b.group[u(i)] / b.armed[u(i)], 0.0, 1.0) : 0.0;
    if (i >= su.codes) continue;
    h.event_prob[u(i)] = b.ours[u(i)] * per_cycle;
    h.background_event_prob[u(i)] = b.ours_background[u(i)] * per_cycle;
    h.group_events_per_cycle += b.group[u(i)] * per_cycle;
    h.our_events_per_cycle += h.event_prob[u(i)];
  }
  return h;
}

// The first arming's state: P(last winner's class) by the classes' rates, the laws those of a hit
// in (one of) the bins arming there, its losers live at the hit.
ArmState initial_state(const Setup& su) {
  ArmState st;
  st.omega.assign(u(su.nc), Vec(u(su.np), 0.0));
  double total = 0;
  Vec weight(u(su.nc), 0.0);
  for (int c = 0; c < su.nc; ++c) {
    for (double q : su.fp[u(c)].q) weight[u(c)] += su.count[u(c)] * q;
    total += weight[u(c)];
  }
  for (int c = 0; c < su.nc; ++c) std::fill(st.omega[u(c)].begin(), st.omega[u(c)].end(), weight[u(c)] / total);
  st.win.assign(u(su.nc), std::vector<LawMix>(u(su.np)));
  st.lose = st.win;
  for (int c = 0; c < su.nc; ++c)
    for (int phi = 0; phi < su.np; ++phi) {
      const int h = su.hits_arming_at[u(phi)].empty() ? phi : su.hits_arming_at[u(phi)].front();
      const LawTable& w = su.winner[u(c)];
      const LawTable& f = su.fresh[u(c)];
      st.win[u(c)][u(phi)] = {LawPart{w.ret_of(h), w.live[u(h)], w.dead_total[u(h)], 1.0, LawPart::kWinner}};
      st.lose[u(c)][u(phi)] = {LawPart{f.ret_of(h), f.live[u(h)], f.dead_total[u(h)], 1.0, LawPart::kFresh}};
    }
  SpadLaw live;
  live.live = 1, live.ret.assign(u(su.dead), 0.0);
  st.pool.assign(u(su.nc), live);
  return st;
}

// A first guess of the arming phase's law, so that the first pass's sums are nearly weighted
// right: the TDC's chain without SPAD memory (pile_up.h) on the group's mean-field rates, its
// hits per bin moved to where they arm the TDC.
Vec initial_arming_law(const DeadTimeChainInput& in, const Setup& su) {
  PileUpInput mf;
  mf.photons_per_bin.assign(u(su.np), 0.0);
  for (const auto& c : in.classes) {
    double mean = 0;
    for (double a : c.arrivals) mean += a;
    const double live = 1 / (1 + mean / su.np * su.dead);  // stationary live fraction
    for (int i = 0; i < su.np; ++i) mf.photons_per_bin[u(i)] += std::max(0, c.count) * c.arrivals[u(i)] * live;
  }
  mf.codes = su.codes, mf.share = 1;
  mf.block_event_bins = in.block_event_bins, mf.block_overflow_bins = in.block_overflow_bins;
  const PileUpHistogram h = expected_histogram(mf);
  Vec pi(u(su.np), 0.0);
  double z = 0;
  for (int i = 0; i < su.np; ++i) {
    const double hits = h.armed_prob[u(i)] * h.hazard[u(i)];
    pi[u(su.arm_phase[u(i)])] += hits, z += hits;
  }
  for (double& x : pi) x = z > 0 ? x / z : 1.0 / su.np;
  return pi;
}

// Per thread: the chain runs once per operating point, its tables are reused (no page faults).
struct Workspace {
  Setup setup;
  chain::Lockstep lockstep;
  Book book;
  PoolBook pool;
  Vec scratch;
};
Workspace& workspace() {
  static thread_local Workspace w;
  return w;
}

}  // namespace

long long dead_time_chain_work(const DeadTimeChainInput& in) {
  const long long np = in.classes.empty() ? 0 : static_cast<long long>(in.classes.front().arrivals.size());
  const long long longest =
      std::max({static_cast<long long>(in.block_event_bins), static_cast<long long>(in.block_overflow_bins), np});
  return np * (2LL * in.dead_bins + longest + np);  // the laws' free runs, the windows, the transitions
}

PileUpHistogram dead_time_histogram(const DeadTimeChainInput& in) {
  assert(!in.classes.empty() && in.dead_bins >= 1 && in.codes > 0);
  Workspace& ws = workspace();
  Setup& su = ws.setup;
  chain::build_setup(in, su);
  ws.lockstep.build(su);
  if (ws.lockstep.on) {  // the lockstep pass keeps the laws itself; the chain needs their masses
    su.winner.resize(1), su.fresh.resize(1);
    su.winner[0].reset_totals(su.np, su.dead), su.fresh[0].reset_totals(su.np, su.dead);
    su.winner[0].live = ws.lockstep.winner_live, su.winner[0].dead_total = ws.lockstep.winner_dead;
    su.fresh[0].live = ws.lockstep.fresh_live, su.fresh[0].dead_total = ws.lockstep.fresh_dead;
  } else {
    chain::build_law_tables(su);
  }
  if (!(su.one_minus_q > 0)) {  // nothing ever fires: always armed, no events
    PileUpHistogram h;
    h.share = in.share, h.model = kModel, h.converged = true;
    h.event_prob.assign(u(su.codes), 0.0), h.background_event_prob = h.event_prob;
    h.armed_prob.assign(u(su.np), 1.0), h.hazard.assign(u(su.np), 0.0);
    return h;
  }
  ArmState st = initial_state(su);
  Vec pi = initial_arming_law(in, su), pi_before;
  Book& b = ws.book;
  PileUpHistogram h;
  double last_events = -1, last_armed = -1;
  bool track_pool = true;
  const double pass_work = static_cast<double>(su.np) * (su.dead + 60.0 * su.np);
  const int max_passes = static_cast<int>(std::clamp(kWorkBudget / pass_work, 3.0, static_cast<double>(kMaxPasses)));
  for (int it = 1; it <= max_passes; ++it) {
    b.reset(su.np, su.nc);
    ws.pool.reset(su.nc, su.dead);
    ws.pool.track = track_pool;
    if (ws.lockstep.on) {
      chain::lockstep_pass(su, ws.lockstep, st, pi, b, ws.pool, ws.scratch);
    } else {
      for (int phi = 0; phi < su.np; ++phi)
        for (int cw = 0; cw < su.nc; ++cw)
          if (const double om = st.omega[u(cw)][u(phi)]; om > 0)
            chain::armed_window(su, st, phi, cw, om, pi[u(phi)] * om, b, ws.pool, ws.scratch);
    }
    chain::add_tails(su, b);
    pi_before = pi;
    stationary(b.transition, pi);
    double moved = 0;
    for (size_t i = 0; i < pi.size(); ++i) moved += std::fabs(pi[i] - pi_before[i]);
    h = finish(su, b, in.share);
    h.iterations = it;
    double armed = 0;
    for (double a : h.armed_prob) armed += a;
    if (std::fabs(h.group_events_per_cycle - last_events) <= kTolerance * h.group_events_per_cycle &&
        std::fabs(armed - last_armed) <= kTolerance * armed && moved < kTolerance) {
      h.converged = true;
      break;
    }
    last_events = h.group_events_per_cycle, last_armed = armed;
    // Losers still dead at a hit: their pooled law matters only when there are any.
    double dead = 0, losers = 0;
    for (int c = 0; c < su.nc; ++c)
      for (int i = 0; i < su.np; ++i) dead += b.dead[u(c)][u(i)], losers += b.fresh[u(c)][u(i)] + b.fired[u(c)][u(i)];
    const bool was_tracked = ws.pool.track;
    track_pool = dead > 1e-12 * (dead + losers);
    if (was_tracked)
      update_state(su, b, ws.pool, st);
    else
      update_state(su, b, ws.pool, st, false);
  }
  return h;
}

}  // namespace rangesim::golden::spad
