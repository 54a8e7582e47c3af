#include "golden/tof_spad/dead_time_lockstep.h"

#include <algorithm>

namespace rangesim::golden::spad::chain {

namespace {

size_t u(long long i) { return static_cast<size_t>(i); }

// x^n, n the losers' count less one: unrolled for the usual small groups (N < 0: any n, by
// squaring; a TDC may serve thousands of columns).
template <int N>
inline double pow_n(double x, int n) {
  double r = 1;
  if constexpr (N >= 0) {
    for (int i = 0; i < N; ++i) r *= x;
  } else {
    for (; n > 0; n >>= 1, x *= x)
      if (n & 1) r *= x;
  }
  return r;
}

double sum(const double* v, int n) {
  double s = 0;
  for (int i = 0; i < n; ++i) s += v[i];
  return s;
}

// Per arming phase, the state of its window (arrays over phi).
struct Lanes {
  Vec w, a_fresh, a_fired, a_pool, live0, dead0, live1, dead1, z0, z1;
  explicit Lanes(int np) {
    for (Vec* v : {&w, &a_fresh, &a_fired, &a_pool, &live0, &dead0, &live1, &dead1, &z0, &z1}) v->assign(u(np), 0.0);
  }
};

// The lanes [lo, hi) in window bin t, whose TDC bins are s = phi + shift.
struct Segment {
  int lo, hi, shift;
};

// One bin of one segment for every lane: the same algebra as armed_window's step, branch free.
// Only what varies per lane is summed here (the book's bins); the rest follows from `group` and
// the hits after the pass. kPool: the pool's terms are wanted.
template <int N, bool kPool>
void lanes_kernel(int lo, int hi, int n, double pool_r, const double* __restrict wt, const double* __restrict ft,
                  const double* __restrict q, const double* __restrict qh, const double* __restrict w,
                  const double* __restrict af, const double* __restrict aw, const double* __restrict ap,
                  double* __restrict armed, double* __restrict fired, double* __restrict fresh, double* __restrict dead,
                  double* __restrict group, double* __restrict live0, double* __restrict dead0,
                  double* __restrict live1, double* __restrict dead1, double* __restrict z0s, double* __restrict z1s,
                  double* __restrict hits) {
  const double nn = n;
  for (int i = lo; i < hi; ++i) {
    const double r0 = wt[i], r1 = af[i] * ft[i] + aw[i] * wt[i] + ap[i] * pool_r;
    const double d0 = std::max(0.0, dead0[i] - r0), d1 = std::max(0.0, dead1[i] - r1);
    const double s0 = live0[i] + r0 + d0, s1 = live1[i] + r1 + d1;
    const double f0 = live0[i] * q[i] + r0 * qh[i], f1 = live1[i] * q[i] + r1 * qh[i];
    const double n0 = s0 - f0, n1 = s1 - f1;
    const double s1p = pow_n<N>(s1, n - 1), n1p = pow_n<N>(n1, n - 1);
    const double s_all = s0 * s1p * s1, p = s_all - n0 * n1p * n1;
    const double z0 = s1p * s1 - n1p * n1, z1 = s0 * s1p - n0 * n1p;  // the others of one SPAD hit in t
    const double wi = w[i];
    armed[i] += wi * s_all;
    fired[i] += wi * (f0 * s1p * s1 + nn * f1 * s0 * s1p - p);
    fresh[i] += wi * (z0 * (n0 - d0) + nn * z1 * (n1 - d1));
    dead[i] += wi * (z0 * d0 + nn * z1 * d1);
    group[i] += wi * p;
    if constexpr (kPool) z0s[i] = wi * z0, z1s[i] = wi * nn * z1;
    hits[i] = p;
    live0[i] = n0 - d0, dead0[i] = d0, live1[i] = n1 - d1, dead1[i] = d1;
  }
}

template <int N, bool kPool>
void lanes_bin(const Setup& su, const Lockstep& ls, int t, const Segment& g, double pool_r, int n, Lanes& l, Book& b,
               double* hit_row) {
  const size_t row = u(t) * u(su.np);
  const int sh = g.shift;
  lanes_kernel<N, kPool>(g.lo, g.hi, n, pool_r, ls.winner_t.data() + row, ls.fresh_t.data() + row,
                         su.fp[0].q.data() + sh, su.fp[0].qh.data() + sh, l.w.data(), l.a_fresh.data(),
                         l.a_fired.data(), l.a_pool.data(), b.armed.data() + sh, b.fired[0].data() + sh,
                         b.fresh[0].data() + sh, b.dead[0].data() + sh, b.group.data() + sh, l.live0.data(),
                         l.dead0.data(), l.live1.data(), l.dead1.data(), l.z0.data(), l.z1.data(), hit_row);
}

template <int N, bool kPool>
void all_bins(const Setup& su, const Lockstep& ls, const Vec& pool_ret, int n, Lanes& l, Book& b, PoolBook& pool,
              Vec& hits) {
  const int np = su.np;
  for (int t = 0; t < su.dead; ++t) {
    const int off = t % np;
    double* hit_row = hits.data() + u(t) * u(np);
    lanes_bin<N, kPool>(su, ls, t, {0, np - off, off}, pool_ret[u(t)], n, l, b, hit_row);
    lanes_bin<N, kPool>(su, ls, t, {np - off, np, off - np}, pool_ret[u(t)], n, l, b, hit_row);
    if constexpr (kPool) {
      pool.weight[0][0][u(t)] += sum(l.z0.data(), np), pool.weight[0][1][u(t)] += sum(l.z1.data(), np);
      // The recharge laws weighted like the book: the winner's, and the losers' mixture.
      double r0 = 0, r1 = 0;
      const double* wt = ls.winner_t.data() + u(t) * u(np);
      const double* ft = ls.fresh_t.data() + u(t) * u(np);
      for (int i = 0; i < np; ++i) {
        r0 += l.w[u(i)] * wt[i];
        r1 += l.w[u(i)] * (l.a_fresh[u(i)] * ft[i] + l.a_fired[u(i)] * wt[i] + l.a_pool[u(i)] * pool_ret[u(t)]);
      }
      pool.law_sum[0][0][u(t)] += r0, pool.law_sum[0][1][u(t)] += r1;
    }
  }
}

// Free run of every hit bin's SPAD at once (lane h: from bin h + from to its arming h + arm):
// live_mass live from the start, or a recharge at the start; the law at the arming goes to
// table[d * np + arming phase].
void lanes_free_run(const Setup& su, long long from, long long arm, bool live_start, Vec& ring, Vec& table, Vec& live,
                    Vec& dead_total) {
  const int np = su.np, dead = su.dead;
  const size_t n = u(np);
  ring.assign(u(dead) * n, 0.0);
  live.assign(n, live_start ? 1.0 : 0.0);
  if (!live_start)
    std::fill(ring.begin() + static_cast<long>(u(from % dead) * n),
              ring.begin() + static_cast<long>(u(from % dead) * n + n), 1.0);
  const double* q0 = su.fp[0].q.data();
  const double* qh0 = su.fp[0].qh.data();
  for (long long j = from; j < arm; ++j) {
    const int off = static_cast<int>(j % np);
    double* __restrict r = ring.data() + u(j % dead) * n;
    double* __restrict lv = live.data();
    for (const Segment g : {Segment{0, np - off, off}, Segment{np - off, np, off - np}}) {
      const double* __restrict q = q0 + g.shift;
      const double* __restrict qh = qh0 + g.shift;
      for (int i = g.lo; i < g.hi; ++i) {
        const double rc = r[i];
        r[i] = lv[i] * q[i] + rc * qh[i];  // avalanches now recharge dead bins later
        lv[i] = lv[i] * (1 - q[i]) + rc * (1 - qh[i]);
      }
    }
  }
  // The law at the arming, by arming phase (h + arm mod np).
  table.resize(u(dead) * n);
  dead_total.assign(n, 0.0);
  const int shift = static_cast<int>(arm % np);
  for (int d = 0; d < dead; ++d) {
    const double* r = ring.data() + u((arm + d) % dead) * n;
    double* out = table.data() + u(d) * n;
    for (int h = 0; h < np; ++h) {
      const int phi = h + shift < np ? h + shift : h + shift - np;
      out[phi] = r[h], dead_total[u(h)] += r[h];
    }
  }
}

}  // namespace

void Lockstep::build(const Setup& su) {
  // One class of two or more SPADs, every hit bin arming the same number of bins later (then each
  // phase is armed from exactly one bin).
  on = su.nc == 1 && su.count[0] >= 2;
  for (int h = 0; h < su.np && on; ++h) on = su.arm_offset[u(h)] == su.arm_offset[0];
  if (!on) return;
  const long long e = su.arm_offset[0];
  hit_of_phase.resize(u(su.np));
  for (int h = 0; h < su.np; ++h) hit_of_phase[u(su.arm_phase[u(h)])] = h;
  Vec ring, live, dead_total;
  // Winner: recharging dead bins after its avalanche; fresh loser: live from the next bin.
  if (e > su.dead) {
    lanes_free_run(su, su.dead, e, false, ring, winner_t, live, dead_total);
  } else {  // still dead at the arming: recharging dead - e bins after it
    winner_t.assign(u(su.dead) * u(su.np), 0.0), live.assign(u(su.np), 0.0), dead_total.assign(u(su.np), 1.0);
    std::fill(winner_t.begin() + static_cast<long>(u(su.dead - e) * u(su.np)),
              winner_t.begin() + static_cast<long>(u(su.dead - e + 1) * u(su.np)), 1.0);
  }
  winner_live = live, winner_dead = dead_total;
  lanes_free_run(su, 1, e, true, ring, fresh_t, live, dead_total);
  fresh_live = live, fresh_dead = dead_total;
  arm_offset.resize(u(su.np));
  for (int s = 0; s < su.np; ++s) arm_offset[u(s)] = static_cast<double>(su.arm_offset[u(s)]);
}

void lockstep_pass(const Setup& su, const Lockstep& ls, const ArmState& st, const Vec& pi, Book& b, PoolBook& pool,
                   Vec& hits) {
  const int np = su.np, n = su.count[0] - 1, dead = su.dead;
  Lanes l(np);
  for (int phi = 0; phi < np; ++phi) {
    const size_t i = u(phi);
    l.w[i] = pi[i];
    const LawPart& win = st.win[0][i].front();
    l.live0[i] = win.live, l.dead0[i] = win.dead;
    for (const LawPart& p : st.lose[0][i]) {
      (p.src == LawPart::kFresh ? l.a_fresh : p.src == LawPart::kWinner ? l.a_fired : l.a_pool)[i] += p.w;
      l.live1[i] += p.w * p.live, l.dead1[i] += p.w * p.dead;
    }
  }
  hits.resize(u(dead) * u(np));
  const Vec& pool_ret = st.pool[0].ret;
  const bool track = pool.track;
  if (n == 3)
    track ? all_bins<2, true>(su, ls, pool_ret, n, l, b, pool, hits)
          : all_bins<2, false>(su, ls, pool_ret, n, l, b, pool, hits);
  else
    track ? all_bins<-1, true>(su, ls, pool_ret, n, l, b, pool, hits)
          : all_bins<-1, false>(su, ls, pool_ret, n, l, b, pool, hits);
  if (track) {
    const double weight = sum(l.w.data(), np);
    pool.law_weight[0][0] += weight, pool.law_weight[0][1] += weight;
  }
  // What is the same for every lane of a bin: one class wins every hit, our pixel a 1 / M share,
  // the bins from the hit to the next arming.
  for (int s = 0; s < np; ++s) {
    const double g = b.group[u(s)], ours = g / su.count[0];
    b.wins[0][u(s)] += g, b.ours[u(s)] += ours, b.ours_background[u(s)] += ours * su.background_fraction[u(s)];
    b.hit_offset += g * ls.arm_offset[u(s)], b.length += g * ls.arm_offset[u(s)];
  }
  // Transitions (a hit in bin t of the window armed at phi arms the TDC at arm_phase[phi + t]),
  // the bins from the arming to the hit and the laser cycles with armed time.
  for (int t = 0; t < dead; ++t) {
    const double* hit_row = hits.data() + u(t) * u(np);
    double hits_t = 0, later_cycle = 0;
    for (int phi = 0, s = t % np; phi < np; ++phi, s = s + 1 == np ? 0 : s + 1) {
      b.transition[u(phi) * u(np) + u(su.arm_phase[u(s)])] += hit_row[phi];
      const double wp = l.w[u(phi)] * hit_row[phi];
      hits_t += wp;
      if (phi + t % np >= np) later_cycle += wp;  // the hit's bin is in the next laser cycle
    }
    b.length += hits_t * t;
    b.armed_cycles += hits_t * (t / np + 1) + later_cycle;
  }
  for (int phi = 0; phi < np; ++phi) {
    const size_t i = u(phi);
    const double s0 = l.live0[i] * pow_n<-1>(l.live1[i], n);
    b.tail_mass[i] += l.w[i] * s0, b.tail_row[i] += s0;
  }
}

}  // namespace rangesim::golden::spad::chain
