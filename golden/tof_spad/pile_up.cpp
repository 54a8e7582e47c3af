#include "golden/tof_spad/pile_up.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace rangesim::golden::spad {

double tdc_share(int columns_per_tdc, double neighbour_rate_fraction) {
  return 1.0 + (columns_per_tdc - 1) * neighbour_rate_fraction;
}

PileUpHistogram expected_histogram(const PileUpInput& in) {
  const int np = static_cast<int>(in.photons_per_bin.size());
  assert(np > 0 && in.codes > 0 && in.codes <= np && in.share >= 1);
  PileUpHistogram h;
  h.share = in.share;
  h.hazard.resize(static_cast<size_t>(np));
  for (int i = 0; i < np; ++i)
    h.hazard[static_cast<size_t>(i)] = -std::expm1(-in.share * in.photons_per_bin[static_cast<size_t>(i)]);

  // Where a hit in bin i re-arms the group: the cycle offset k (0 = same cycle, the TDC stays
  // stopped until the next START) and the arming phase v of the k-th cycle.
  std::vector<int> next_phase(static_cast<size_t>(np)), cycles_used(static_cast<size_t>(np));
  for (int i = 0; i < np; ++i) {
    const long long dest = static_cast<long long>(i) + (i < in.codes ? in.block_event_bins : in.block_overflow_bins);
    const bool carries = dest >= np;
    next_phase[static_cast<size_t>(i)] = carries ? static_cast<int>(dest % np) : 0;
    cycles_used[static_cast<size_t>(i)] = carries ? static_cast<int>(dest / np) : 1;
  }

  std::vector<double> w(static_cast<size_t>(np), 0.0), next(static_cast<size_t>(np)), armed(static_cast<size_t>(np)),
      hit(static_cast<size_t>(np));
  w[0] = 1.0;  // first cycle: armed from START
  double cycles = 1;
  const int max_iterations = 200000, lazy_after = 2000;
  for (h.iterations = 1; h.iterations <= max_iterations; ++h.iterations) {
    std::fill(next.begin(), next.end(), 0.0);
    double alive = 0;  // P(armed at the start of bin i), summed over arming phases u <= i
    cycles = 0;
    for (int i = 0; i < np; ++i) {
      const auto ui = static_cast<size_t>(i);
      alive += w[ui];
      armed[ui] = alive;
      hit[ui] = alive * h.hazard[ui];
      alive -= hit[ui];
      next[static_cast<size_t>(next_phase[ui])] += hit[ui];
      cycles += hit[ui] * cycles_used[ui];
    }
    next[0] += alive;  // no hit in the period: armed again at the next START
    cycles += alive;
    double diff = 0;
    // A chain whose blocking is a whole number of periods can be (nearly) periodic: after
    // lazy_after iterations damp it (same stationary law, aperiodic).
    const double keep = h.iterations > lazy_after ? 0.5 : 0.0;
    for (int i = 0; i < np; ++i) {
      const auto ui = static_cast<size_t>(i);
      const double v = keep * w[ui] + (1 - keep) * next[ui];
      diff += std::fabs(v - w[ui]);
      w[ui] = v;
    }
    if (diff < 1e-13) {
      h.converged = true;
      break;
    }
  }
  h.cycles_per_live_cycle = cycles;
  h.event_prob.resize(static_cast<size_t>(in.codes));
  h.armed_prob.resize(static_cast<size_t>(np));
  double events = 0;
  for (int i = 0; i < np; ++i) {
    const auto ui = static_cast<size_t>(i);
    h.armed_prob[ui] = armed[ui] / cycles;
    if (i < in.codes) {
      events += hit[ui] / cycles;
      h.event_prob[ui] = hit[ui] / cycles / in.share;
    }
  }
  h.group_events_per_cycle = events;
  h.our_events_per_cycle = events / in.share;
  return h;
}

}  // namespace rangesim::golden::spad
