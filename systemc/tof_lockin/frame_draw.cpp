#include "systemc/tof_lockin/frame_draw.h"

#include <algorithm>
#include <cmath>

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
                      bool tables_allowed) {
  const double a = cfg.pixel.source_follower_gain;
  laws_.assign(frame_mean_e.size(), TapFrameLaw{});
  tables_.clear();
  std::map<double, int> means;
  for (std::size_t i = 0; i < frame_mean_e.size(); ++i) {
    TapFrameLaw& l = laws_[i];
    const int tap = static_cast<int>(i % 2);
    l.offset_e = offset_e[tap];
    l.count_mean_e = std::max(0.0, frame_mean_e[i]) + l.offset_e;
    l.ktc_fd_V = golden::ktc_noise_V(cfg, tap) / a;
    l.read_V = cfg.noise.read_noise_V;
    l.may_saturate = swing_may_saturate(cfg, tap, l.count_mean_e, l.offset_e);
    l.sigma_V = std::sqrt(a * a * l.ktc_fd_V * l.ktc_fd_V + l.read_V * l.read_V);
    if (l.count_mean_e <= PoissonAlias::kMaxMean) ++means[l.count_mean_e];
  }
  const bool tables = tables_allowed && means.size() <= kMaxTables;
  for (TapFrameLaw& l : laws_) {
    if (tables && l.count_mean_e <= PoissonAlias::kMaxMean) {
      auto& t = tables_[l.count_mean_e];
      if (!t) t = std::make_unique<PoissonAlias>(l.count_mean_e);
      l.table = t.get();
    } else if (l.count_mean_e <= 1e15) {
      l.ptrs = PoissonSampler(l.count_mean_e);
    }
  }
}

}  // namespace rangesim::systemc::lockin
