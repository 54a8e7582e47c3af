#include "golden/tof_spad/dead_time_window.h"

#include <algorithm>
#include <cmath>

namespace rangesim::golden::spad::chain {

namespace {

size_t u(long long i) { return static_cast<size_t>(i); }

double int_pow(double x, int n) {
  double r = 1;
  for (; n > 0; n >>= 1, x *= x)
    if (n & 1) r *= x;
  return r;
}

// Effective rate of a bin where a SPAD fires with probability a: Poisson competition inside the
// bin splits a hit between the SPADs firing there in proportion to it (capped: exp(-700) is 0).
double rate_of(double a) { return a < 1 ? std::min(-std::log1p(-a), 700.0) : 700.0; }

// One SPAD kind in an armed window: the last winner, or the losers of a class. Its law at the
// arming is a mixture of up to three stored laws, read bin by bin.
struct Kind {
  int cls = 0, n = 0, kind = 0;  // kind 0: the last winner, 1: losers
  const double* ret[3] = {nullptr, nullptr, nullptr};
  double w[3] = {0, 0, 0};
  int parts = 0;
  const FiringProbs* fp = nullptr;
  double live = 0, dead = 0;  // running: live and silent so far; recharging later
  double s = 0, f = 0, r = 0;
  double recharge(int t) const {
    double x = 0;
    for (int i = 0; i < parts; ++i) x += w[i] * ret[i][t];
    return x;
  }
};

}  // namespace

void LawTable::reset(int n, int dead_bins) {
  dead = dead_bins;
  live.assign(u(n), 0.0);
  ret.assign(u(n) * u(dead_bins), 0.0);
  dead_total.assign(u(n), 0.0);
}

void LawTable::reset_totals(int n, int dead_bins) {
  dead = dead_bins;
  live.assign(u(n), 0.0);
  ret.clear();
  dead_total.assign(u(n), 0.0);
}

void LawTable::finish(int i) {
  double t = 0;
  for (const double* r = ret_of(i); r != ret_of(i) + dead; ++r) t += *r;
  dead_total[u(i)] = t;
}

void build_setup(const DeadTimeChainInput& in, Setup& s) {
  s.count.clear(), s.fp.clear(), s.flat.clear();
  for (const auto& c : in.classes) {
    if (c.count <= 0) continue;
    s.count.push_back(c.count);
    s.fp.push_back(firing_probs(c.arrivals));
    s.flat.push_back(flat_firing_probs(c.arrivals));
  }
  s.nc = static_cast<int>(s.count.size());
  s.np = static_cast<int>(in.classes.front().arrivals.size());
  s.codes = in.codes;
  s.dead = in.dead_bins;
  const auto& ours = in.classes.front();
  s.background_fraction.resize(u(s.np));
  for (int i = 0; i < s.np; ++i) {
    const double a = ours.arrivals[u(i)];
    s.background_fraction[u(i)] = a > 0 ? std::clamp(1 - ours.signal_arrivals[u(i)] / a, 0.0, 1.0) : 1.0;
  }
  s.arm_offset.resize(u(s.np));
  s.arm_phase.resize(u(s.np));
  s.hits_arming_at.assign(u(s.np), {});
  for (int h = 0; h < s.np; ++h) {
    const long long block = h < s.codes ? in.block_event_bins : in.block_overflow_bins;
    const long long e = std::max(block, static_cast<long long>(s.np - h));  // a stopped TDC waits for START
    s.arm_offset[u(h)] = e;
    s.arm_phase[u(h)] = static_cast<int>((h + e) % s.np);
    s.hits_arming_at[u(s.arm_phase[u(h)])].push_back(h);
  }
  s.silent.assign(u(s.np), 1.0);
  s.rate.assign(u(s.nc), Vec(u(s.np)));
  double log_q = 0;
  for (int i = 0; i < s.np; ++i) {
    double log_silent = 0;
    for (int c = 0; c < s.nc; ++c) {
      const double q = std::min(s.fp[u(c)].q[u(i)], 1.0);
      log_silent += s.count[u(c)] * std::log1p(-q);
      s.rate[u(c)][u(i)] = rate_of(q);
    }
    s.silent[u(i)] = std::exp(log_silent);
    log_q += log_silent;
  }
  s.one_minus_q = -std::expm1(log_q);
  // From each start bin with every SPAD live: P(the hit arms the TDC at each phase), over all
  // later periods.
  s.tail_transition.assign(u(s.np) * u(s.np), 0.0);
  if (!(s.one_minus_q > 0)) return;
  const double g0 = 1 / s.one_minus_q;
  for (int s0 = 0; s0 < s.np; ++s0) {
    double surv = g0;
    double* row = s.tail_transition.data() + u(s0) * u(s.np);
    for (int i = 0, b = s0; i < s.np; ++i, b = b + 1 == s.np ? 0 : b + 1) {
      row[s.arm_phase[u(b)]] += surv * (1 - s.silent[u(b)]);
      surv *= s.silent[u(b)];
    }
  }
}

void build_law_tables(Setup& s) {
  s.winner.resize(u(s.nc));
  s.fresh.resize(u(s.nc));
  Vec ring(u(s.dead));
  const double one = 1.0;
  for (int c = 0; c < s.nc; ++c) {
    LawTable& win = s.winner[u(c)];
    LawTable& fresh = s.fresh[u(c)];
    win.reset(s.np, s.dead), fresh.reset(s.np, s.dead);
    for (int h = 0; h < s.np; ++h) {
      // Winner: dead from its avalanche in bin h, recharging in bin h + dead. Fresh loser: live
      // and silent through bin h (memoryless from there).
      const long long arm = h + s.arm_offset[u(h)], back = h + s.dead;
      if (back >= arm)  // still dead at the arming
        win.ret_of(h)[back - arm] = 1;
      else
        free_run_into(s.fp[u(c)], s.dead, back, 0.0, &one, 1, arm, ring.data(), win.live[u(h)], win.ret_of(h));
      win.finish(h);
      free_run_into(s.fp[u(c)], s.dead, h + 1, 1.0, nullptr, 0, arm, ring.data(), fresh.live[u(h)], fresh.ret_of(h));
      fresh.finish(h);
    }
  }
}

void Book::reset(int np_, int nc) {
  np = np_;
  for (auto* vs : {&wins, &fresh, &fired, &dead}) {
    vs->resize(u(nc));
    for (Vec& v : *vs) v.assign(u(np), 0.0);
  }
  for (Vec* v : {&group, &ours, &ours_background, &armed, &tail_mass, &tail_row}) v->assign(u(np), 0.0);
  transition.assign(u(np) * u(np), 0.0);
  length = armed_cycles = hit_offset = 0;
}

void PoolBook::reset(int nc, int dead) {
  weight.resize(u(nc));
  law_sum.resize(u(nc));
  for (auto* vs : {&weight, &law_sum})
    for (auto& pair : *vs)
      for (Vec& v : pair) v.assign(u(dead), 0.0);
  law_weight.assign(u(nc), {0.0, 0.0});
}

// The one-class window (the usual flat scene: every column of the group sees our rates), bins
// [t0, t1): the last winner (kind 0) and n identical losers (kind 1); the same sums as the general
// step, unrolled.
void one_class_dead_loop(const Setup& su, int t0, int t1, int phi, double omega, double weight, Book& b, PoolBook& pool,
                         Kind& k0, Kind& k1) {
  const int n = k1.n;
  const double* q = su.fp[0].q.data();
  const double* qh = su.fp[0].qh.data();
  double* armed = b.armed.data();
  double* wins = b.wins[0].data();
  double* fired = b.fired[0].data();
  double* fresh = b.fresh[0].data();
  double* dead = b.dead[0].data();
  double* group = b.group.data();
  double* ours = b.ours.data();
  double* ours_bg = b.ours_background.data();
  double* pool0 = pool.weight[0][0].data();
  double* pool1 = pool.weight[0][1].data();
  double* row = b.transition.data() + u(phi) * u(su.np);
  const double w_ours = weight / su.count[0];
  double length = 0, armed_cycles = 0, hit_offset = 0;
  int s = static_cast<int>((phi + t0) % su.np), cycle = (phi + t0) / su.np;
  for (int t = t0; t < t1; ++t) {
    const double r0 = k0.recharge(t), r1 = k1.recharge(t);
    k0.dead = std::max(0.0, k0.dead - r0), k1.dead = std::max(0.0, k1.dead - r1);
    const double s0 = k0.live + r0 + k0.dead, s1 = k1.live + r1 + k1.dead;
    const double f0 = k0.live * q[s] + r0 * qh[s], f1 = k1.live * q[s] + r1 * qh[s];
    const double n0 = s0 - f0, n1 = s1 - f1;
    const double s1p = int_pow(s1, n - 1), n1p = int_pow(n1, n - 1);
    const double s_all = s0 * s1p * s1, p_hit = s_all - n0 * n1p * n1;
    armed[s] += weight * s_all;
    if (p_hit > 0) {
      const double z0 = s1p * s1 - n1p * n1, z1 = s0 * s1p - n0 * n1p;  // the others of one SPAD hit in t
      const double fired_all = f0 * s1p * s1 + n * f1 * s0 * s1p;
      const double wp = weight * p_hit;
      wins[s] += wp;
      fired[s] += weight * (fired_all - p_hit);
      fresh[s] += weight * (z0 * (n0 - k0.dead) + n * z1 * (n1 - k1.dead));
      dead[s] += weight * (z0 * k0.dead + n * z1 * k1.dead);
      pool0[t] += weight * z0, pool1[t] += weight * n * z1;
      group[s] += wp;
      ours[s] += w_ours * p_hit, ours_bg[s] += w_ours * p_hit * su.background_fraction[u(s)];
      const double off = static_cast<double>(su.arm_offset[u(s)]);
      length += wp * (t + off), armed_cycles += wp * (cycle + 1), hit_offset += wp * off;
      row[su.arm_phase[u(s)]] += omega * p_hit;
    }
    k0.live = n0 - k0.dead, k1.live = n1 - k1.dead;
    if (++s == su.np) s = 0, ++cycle;
  }
  b.length += length, b.armed_cycles += armed_cycles, b.hit_offset += hit_offset;
}

void armed_window(const Setup& su, const ArmState& st, int phi, int cw, double omega, double weight, Book& b,
                  PoolBook& pool, Vec& scratch) {
  Kind kinds[3];
  int nk = 0;
  scratch.resize(3 * u(su.dead));
  const auto kind_of = [&](int c, int n, int kind, const LawMix& mix) {
    Kind k;
    k.cls = c, k.n = n, k.kind = kind, k.fp = &su.fp[u(c)];
    for (const LawPart& p : mix) k.live += p.w * p.live, k.dead += p.w * p.dead;
    if (mix.size() <= 3) {
      for (const LawPart& p : mix) k.ret[k.parts] = p.ret, k.w[k.parts++] = p.w;
    } else {  // many hit bins arm here (a TDC that waits for START): mix once
      double* ret = scratch.data() + u(nk) * u(su.dead);
      std::fill(ret, ret + su.dead, 0.0);
      for (const LawPart& p : mix)
        for (int d = 0; d < su.dead; ++d) ret[d] += p.w * p.ret[d];
      k.ret[0] = ret, k.w[0] = 1, k.parts = 1;
    }
    if (weight > 0 && pool.track) {
      Vec& sum = pool.law_sum[u(c)][u(kind)];
      for (int i = 0; i < k.parts; ++i)
        for (int d = 0; d < su.dead; ++d) sum[u(d)] += weight * k.w[i] * k.ret[i][d];
      pool.law_weight[u(c)][u(kind)] += weight;
    }
    return k;
  };
  kinds[nk] = kind_of(cw, 1, 0, st.win[u(cw)][u(phi)]), ++nk;
  for (int c = 0; c < su.nc; ++c)
    if (const int n = su.count[u(c)] - (c == cw); n > 0) kinds[nk] = kind_of(c, n, 1, st.lose[u(c)][u(phi)]), ++nk;
  const bool split = su.nc > 1;  // with one class every hit is that class's: no split needed
  const size_t row = u(phi) * u(su.np);
  const double w_ours = weight / su.count[0];
  // A hit in bin `s`, `t` bins after the arming, with probability p.
  const auto book_hit = [&](int s, long long t, double p) {
    b.group[u(s)] += weight * p;
    b.length += weight * p * static_cast<double>(t + su.arm_offset[u(s)]);
    b.armed_cycles += weight * p * static_cast<double>((phi + t) / su.np + 1);
    b.hit_offset += weight * p * static_cast<double>(su.arm_offset[u(s)]);
    b.transition[row + u(su.arm_phase[u(s)])] += omega * p;
  };
  // Bin t of the window, every kind (masses, not conditioned): S survived to t, F fires in t,
  // N = S - F survives t; powers of one SPAD fewer for "the others".
  const auto step = [&](int t, int s) {
    double s_all = 1, stay = 1, sp[3], np_[3];
    for (int i = 0; i < nk; ++i) {
      Kind& k = kinds[i];
      k.r = k.recharge(t);
      k.dead = std::max(0.0, k.dead - k.r);
      k.s = k.live + k.r + k.dead;
      k.f = k.live * k.fp->q[u(s)] + k.r * k.fp->qh[u(s)];
      sp[i] = int_pow(k.s, k.n - 1), np_[i] = int_pow(k.s - k.f, k.n - 1);
      s_all *= sp[i] * k.s, stay *= np_[i] * (k.s - k.f);
    }
    b.armed[u(s)] += weight * s_all;
    const double p_hit = s_all - stay;
    double lambda = 0, ell[3] = {0, 0, 0}, ours = 0;
    if (split && p_hit > 0)
      for (int i = 0; i < nk; ++i)
        ell[i] = kinds[i].s > 0 ? rate_of(kinds[i].f / kinds[i].s) : 0, lambda += kinds[i].n * ell[i];
    for (int i = 0; i < nk; ++i) {
      Kind& k = kinds[i];
      const double fresh = k.s - k.f - k.dead;  // live and silent through t
      if (p_hit > 0) {
        // The others of one SPAD of kind k: survived to t, and one of them fires in t (z).
        double others = sp[i], others_stay = np_[i];
        for (int j = 0; j < nk; ++j)
          if (j != i) others *= sp[j] * kinds[j].s, others_stay *= np_[j] * (kinds[j].s - kinds[j].f);
        const double z = others - others_stay, fired = k.n * k.f * others;
        const double win = split ? p_hit * k.n * ell[i] / lambda : (i == 0 ? p_hit : 0.0);
        const size_t c = u(k.cls);
        b.wins[c][u(s)] += weight * win;
        b.fired[c][u(s)] += weight * (fired - win);
        b.fresh[c][u(s)] += weight * k.n * z * fresh;
        b.dead[c][u(s)] += weight * k.n * z * k.dead;
        pool.weight[c][u(k.kind)][u(t)] += weight * k.n * z;
        if (k.cls == 0) ours += win;
      }
      k.live = fresh;
    }
    if (p_hit > 0) {
      b.ours[u(s)] += w_ours * ours;
      b.ours_background[u(s)] += w_ours * ours * su.background_fraction[u(s)];
      book_hit(s, t, p_hit);
    }
  };
  const int end = su.dead;  // every recharge is over by then
  int s = phi;
  if (su.nc == 1 && nk == 2) {  // the usual one-class group, unrolled
    one_class_dead_loop(su, 0, end, phi, omega, weight, b, pool, kinds[0], kinds[1]);
    s = static_cast<int>((phi + end) % su.np);
  } else {
    for (int t = 0; t < end; ++t, s = s + 1 == su.np ? 0 : s + 1) step(t, s);
  }
  // Every SPAD still silent is live from here on: the group is memoryless, so the rest of the
  // window depends on the arming only through where it starts (chain::add_tails).
  double s0 = 1;
  for (int i = 0; i < nk; ++i) s0 *= int_pow(kinds[i].live, kinds[i].n);
  b.tail_mass[u(phi)] += weight * s0;
  b.tail_row[u(phi)] += omega * s0;
}

void add_tails(const Setup& su, Book& b) {
  if (!(su.one_minus_q > 0)) return;
  const int np = su.np;
  const size_t n2 = u(np);
  // Transitions: row phi gets its tail's weight times the tail from its start bin.
  for (int phi = 0; phi < np; ++phi) {
    const double w = b.tail_row[u(phi)];
    if (!(w > 0)) continue;
    const double* from = su.tail_transition.data() + u((phi + su.dead) % np) * n2;
    double* to = b.transition.data() + u(phi) * n2;
    for (int j = 0; j < np; ++j) to[j] += w * from[j];
  }
  // The book: the tails' live mass by absolute bin x from the arming cycle's start (the tail of
  // the arming at phi starts at x = phi + dead), over one period each and then every later period
  // weighted Q^m (g0 = 1 / (1 - Q), g1 = sum m Q^m). `alive` is the mass of the tails started at
  // most one period ago, `alive_phi` the same weighted by phi (for the bins since the arming).
  const double q_period = 1 - su.one_minus_q, g0 = 1 / su.one_minus_q, g1 = q_period * g0 * g0;
  const bool split = su.nc > 1;
  double alive = 0, alive_phi = 0;
  for (int x = su.dead; x < su.dead + 2 * np; ++x) {
    if (const int phi = x - su.dead; phi < np) {
      alive += b.tail_mass[u(phi)], alive_phi += b.tail_mass[u(phi)] * phi;
    } else {
      const int gone = phi - np;  // a whole period after its start: counted in the g factors
      alive -= b.tail_mass[u(gone)] * q_period, alive_phi -= b.tail_mass[u(gone)] * q_period * gone;
    }
    const int s = x % np;
    const double silent = su.silent[u(s)], all = alive * g0, p_hit = all * (1 - silent);
    b.armed[u(s)] += all;
    if (p_hit > 0) {
      double lambda = 0, ours = 0;
      for (int c = 0; c < su.nc; ++c) lambda += su.count[u(c)] * su.rate[u(c)][u(s)];
      for (int c = 0; c < su.nc; ++c) {
        const double q = su.fp[u(c)].q[u(s)], n = su.count[u(c)];
        const double win = split ? p_hit * n * su.rate[u(c)][u(s)] / lambda : p_hit;
        b.wins[u(c)][u(s)] += win;
        b.fired[u(c)][u(s)] += all * n * q - win;
        b.fresh[u(c)][u(s)] += all * n * std::max(0.0, (1 - q) - silent);
        if (c == 0) ours += win;
      }
      ours /= su.count[0];
      b.ours[u(s)] += ours, b.ours_background[u(s)] += ours * su.background_fraction[u(s)];
      b.group[u(s)] += p_hit;
      const double off = static_cast<double>(su.arm_offset[u(s)]), first = alive * (1 - silent);
      // Bins since the arming: x - phi in the first period, np more in each later one.
      b.length += g0 * ((x + off) * first - alive_phi * (1 - silent)) + g1 * np * first;
      b.armed_cycles += g0 * first * (x / np + 1) + g1 * first;
      b.hit_offset += p_hit * off;
    }
    alive *= silent, alive_phi *= silent;
  }
}

}  // namespace rangesim::golden::spad::chain
