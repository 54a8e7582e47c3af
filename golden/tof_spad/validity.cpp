#include "golden/tof_spad/validity.h"

#include <algorithm>
#include <cmath>

#include "golden/common/significance.h"

namespace rangesim::golden::spad {

PeakSignificance peak_significance(const HistogramCounts& h, const EstimatorConfig& cfg) {
  double total = 0;
  for (double e : h.events) total += e;
  if (h.events.empty() || total <= 0) return {};
  return peak_significance(h, cfg, peak_bin(h, cfg));
}

PeakSignificance peak_significance(const HistogramCounts& h, const EstimatorConfig& cfg, int peak) {
  PeakSignificance s;
  const int codes = static_cast<int>(h.events.size());
  double total = 0;
  for (double e : h.events) total += e;
  if (codes == 0 || total <= 0) return s;
  s.peak_bin = peak;
  s.window = peak_window(s.peak_bin, cfg.peak_window_bins, codes);
  double out_events = 0, out_armed = 0, in_armed = 0;
  for (int i = 0; i < codes; ++i) {
    const auto u = static_cast<std::size_t>(i);
    if (i >= s.window.lo && i <= s.window.hi) {
      s.window_counts += h.events[u], in_armed += h.armed[u];
    } else {
      out_events += h.events[u], out_armed += h.armed[u];
    }
  }
  if (out_armed <= 0 || in_armed <= 0) return s;  // no outside to learn the background from
  // One pseudo-count outside: an empty outside does not prove a background-free window (a lone
  // dark count must not read as an infinitely significant peak).
  s.background_counts = (out_events + 1) / out_armed * in_armed;
  const long long n = std::llround(s.window_counts);
  const int positions = std::max(1, codes - (s.window.hi - s.window.lo));
  const double log_p = poisson_upper_tail_log(n, s.background_counts) + std::log(static_cast<double>(positions));
  s.sigma = std::max(0.0, sigma_from_log_p(log_p));
  return s;
}

}  // namespace rangesim::golden::spad
