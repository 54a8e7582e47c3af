#include "golden/tof_spad/spad_laws.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace rangesim::golden::spad {

double SpadLaw::dead() const {
  double d = 0;
  for (double x : ret) d += x;
  return d;
}

FiringProbs firing_probs(const std::vector<double>& r) {
  FiringProbs fp;
  fp.q.resize(r.size());
  fp.qh.resize(r.size());
  for (size_t i = 0; i < r.size(); ++i) {
    fp.q[i] = -std::expm1(-r[i]);
    fp.qh[i] = -std::expm1(-0.5 * r[i]);
  }
  return fp;
}

FiringProbs flat_firing_probs(const std::vector<double>& r) {
  double mean = 0;
  for (double x : r) mean += x;
  mean /= static_cast<double>(r.size());
  return firing_probs(std::vector<double>(r.size(), mean));
}

void free_run_into(const FiringProbs& fp, int dead_bins, long long from, double live_mass, const double* recharge,
                   int recharges, long long arm, double* ring, double& live_out, double* ret) {
  assert(dead_bins > 0 && from >= 0 && arm >= from && recharges <= dead_bins);
  const long long np = fp.phase_bins(), dead = dead_bins;
  // ring[b mod dead]: mass recharging during bin b, for the next dead_bins bins.
  std::fill(ring, ring + dead, 0.0);
  for (int j = 0; j < recharges; ++j) ring[(from + j) % dead] += recharge[j];
  double live = live_mass;
  long long ph = from % np, idx = from % dead;
  const double* q = fp.q.data();
  const double* qh = fp.qh.data();
  for (long long b = from; b < arm; ++b) {
    const double r = ring[idx];
    ring[idx] = live * q[ph] + r * qh[ph];  // avalanches now recharge dead_bins later
    live = live * (1 - q[ph]) + r * (1 - qh[ph]);
    if (++ph == np) ph = 0;
    if (++idx == dead) idx = 0;
  }
  live_out = live;
  for (long long d = 0, i = arm % dead; d < dead; ++d, i = i + 1 == dead ? 0 : i + 1) ret[d] = ring[i];
}

SpadLaw free_run(const FiringProbs& fp, int dead_bins, long long from, double live_mass,
                 const std::vector<double>& recharge, long long arm) {
  SpadLaw out;
  out.ret.resize(static_cast<size_t>(dead_bins));
  std::vector<double> ring(static_cast<size_t>(dead_bins));
  free_run_into(fp, dead_bins, from, live_mass, recharge.data(), static_cast<int>(recharge.size()), arm, ring.data(),
                out.live, out.ret.data());
  return out;
}

}  // namespace rangesim::golden::spad
