#include "golden/tof_spad/arrival_rates.h"

#include <algorithm>
#include <cmath>

#include "core/physics.h"

namespace rangesim::golden::spad {

double irf_sigma_s(const TofSpadConfig& cfg) {
  const double pulse_sigma_s = cfg.laser.sigma_per_fwhm * cfg.laser.pulse_fwhm_s;
  return std::hypot(pulse_sigma_s, cfg.spad.jitter_sigma_s);
}

Arrivals make_arrivals(const TofSpadConfig& cfg, double signal_Hz, double background_Hz, double distance_m) {
  Arrivals a;
  a.signal_per_cycle = signal_Hz / cfg.laser.repetition_rate_Hz;
  a.round_trip_s = 2.0 * distance_m / phys::kSpeedOfLight_m_per_s;
  a.pulse_sigma_s = cfg.laser.sigma_per_fwhm * cfg.laser.pulse_fwhm_s;
  a.jitter_sigma_s = cfg.spad.jitter_sigma_s;
  a.uniform_rate_Hz = background_Hz + cfg.spad.dark_count_rate_Hz;
  double signal_Hz_all = signal_Hz;
  if (cfg.multipath.on()) {
    a.returns.push_back({cfg.multipath.relative_amplitude * a.signal_per_cycle,
                         a.round_trip_s + cfg.multipath.extra_path_m / phys::kSpeedOfLight_m_per_s});
    signal_Hz_all *= 1 + cfg.multipath.relative_amplitude;
  }
  a.live_fraction = 1.0 / (1.0 + (signal_Hz_all + a.uniform_rate_Hz) * cfg.spad.dead_time_s);
  return a;
}

BinArrivals bin_arrivals(const TdcBins& bins, const Arrivals& a) {
  const int np = bins.phase_bins;
  BinArrivals r;
  r.total.resize(static_cast<size_t>(np));
  r.signal.assign(static_cast<size_t>(np), 0.0);
  for (int i = 0; i < np; ++i) r.total[static_cast<size_t>(i)] = a.uniform_rate_Hz * bins.width_s(i);
  const auto add = [&](int i, double mass) {
    r.signal[static_cast<size_t>(i)] += mass;
    r.total[static_cast<size_t>(i)] += mass;
  };
  // One echo of `mass` photons per cycle centred at `centre`.
  const auto echo = [&](double mass, double centre) {
    if (!(mass > 0)) return;
    if (a.pulse_sigma_s <= 0) {  // a delta echo lands whole in one bin
      const auto it = std::upper_bound(bins.edges_s.begin(), bins.edges_s.end(), centre);
      const long i = std::distance(bins.edges_s.begin(), it) - 1;
      if (i >= 0 && i < np) add(static_cast<int>(i), mass);
      return;
    }
    // Upper tail Q(x) = erfc(x / sqrt 2) / 2 keeps precision far out on both sides.
    const double k = 1.0 / (std::sqrt(2.0) * a.pulse_sigma_s);
    const double lo = centre - 12 * a.pulse_sigma_s, hi = centre + 12 * a.pulse_sigma_s;
    for (int i = 0; i < np; ++i) {
      const double e0 = bins.edges_s[static_cast<size_t>(i)], e1 = bins.edges_s[static_cast<size_t>(i) + 1];
      if (e1 < lo || e0 > hi) continue;
      add(i, mass * 0.5 * (std::erfc((e0 - centre) * k) - std::erfc((e1 - centre) * k)));
    }
  };
  echo(a.signal_per_cycle, a.round_trip_s);
  for (const Return& e : a.returns) echo(e.signal_per_cycle, e.round_trip_s);
  return r;
}

std::vector<double> photons_per_bin(const TdcBins& bins, const Arrivals& a) {
  std::vector<double> r = bin_arrivals(bins, a).total;
  for (double& x : r) x *= a.live_fraction;
  return r;
}

}  // namespace rangesim::golden::spad
