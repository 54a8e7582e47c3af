#include "systemc/tof_lockin/frame_draw.h"

#include <algorithm>
#include <cmath>
#include <utility>

#include "golden/tof_lockin/tap_charge.h"
#include "systemc/tof_lockin/normal_ziggurat.h"

namespace rangesim::systemc::lockin {

double TapFrameLaw::count_without_table(CounterStream& s) const {
  if (!(count_mean_e > 0.0)) return 0.0;
  if (count_mean_e > 1e15)  // beyond exact integers: Normal(mean, mean), skewness 3e-8
    return std::max(0.0, std::round(count_mean_e + std::sqrt(count_mean_e) * NormalZiggurat::tables()(s)));
  return static_cast<double>(ptrs(s));
}

bool swing_may_saturate(const TofLockinConfig& cfg, int tap, double count_mean_e, double offset_e) {
  const double a = cfg.pixel.source_follower_gain;
  const double g_fd = golden::volts_per_electron(cfg, tap) / a;  // volts on the FD per electron
  const double headroom_V =
      cfg.pixel.saturation_voltage_V - ((count_mean_e - offset_e) * g_fd + cfg.pixel.offset_voltage_V);
  // Bernstein: P(N - M >= t) <= exp(-t^2 / (2 (M + t / 3))) <= 2^-61 for t = c/3 + sqrt(c^2/9 + 2 c M),
  // c = 61 ln 2; P(Z >= 9.1) = 4.5e-20 < 2^-61.
  const double c = 61.0 * std::log(2.0);
  const double t = c / 3.0 + std::sqrt(c * c / 9.0 + 2.0 * c * count_mean_e);
  const double ktc_fd_V = golden::ktc_noise_V(cfg, tap) / a;
  return !(headroom_V > t * g_fd + 9.1 * ktc_fd_V);
}

void FrameLaws::build(const TofLockinConfig& cfg, const std::vector<double>& frame_mean_e, const double offset_e[2],
                      PoissonTables tables, long long frames) {
  const double a = cfg.pixel.source_follower_gain;
  laws_.clear(), pair_.clear(), tables_.clear();
  // Pixels with the same two means share their laws; each count mean's draws over the kernel's frames.
  std::map<std::pair<double, double>, std::uint32_t> pairs;
  std::map<double, long long> draws;
  for (std::size_t p = 0; 2 * p + 1 < frame_mean_e.size(); ++p) {
    double m[2];
    for (int k = 0; k < 2; ++k) m[k] = std::max(0.0, frame_mean_e[2 * p + k]) + offset_e[k], draws[m[k]] += frames;
    const auto [it, added] = pairs.emplace(std::make_pair(m[0], m[1]), static_cast<std::uint32_t>(laws_.size() / 2));
    pair_.push_back(it->second);
    if (!added) continue;
    for (int k = 0; k < 2; ++k) {
      TapFrameLaw l;
      l.offset_e = offset_e[k];
      l.count_mean_e = m[k];
      l.ktc_fd_V = golden::ktc_noise_V(cfg, k) / a;
      l.read_V = cfg.noise.read_noise_V;
      l.may_saturate = swing_may_saturate(cfg, k, l.count_mean_e, l.offset_e);
      l.sigma_V = std::sqrt(a * a * l.ktc_fd_V * l.ktc_fd_V + l.read_V * l.read_V);
      laws_.push_back(l);
    }
  }
  std::size_t entries = 0;
  for (TapFrameLaw& l : laws_) {
    const double m = l.count_mean_e;
    const double size = 19.2 * std::sqrt(m) + 1;  // +-9.6 sigma
    const bool pays = tables == PoissonTables::Always ||
                      (tables == PoissonTables::WhenTheyPay && static_cast<double>(draws[m]) >= size / 2);
    auto it = tables_.find(m);
    if (it == tables_.end() && pays && m <= PoissonAlias::kMaxMean && entries + size <= kMaxTableEntries) {
      it = tables_.emplace(m, std::make_unique<PoissonAlias>(m)).first;
      entries += static_cast<std::size_t>(size);
    }
    if (it != tables_.end()) {
      l.table = it->second.get();
    } else if (m <= 1e15) {
      l.ptrs = PoissonSampler(m);
    }
  }
}

}  // namespace rangesim::systemc::lockin
