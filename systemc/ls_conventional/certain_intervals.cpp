#include "systemc/ls_conventional/certain_intervals.h"

#include <algorithm>
#include <cmath>

#include "golden/common/spot.h"

namespace rangesim::systemc {

CertainIntervals::CertainIntervals(const SpotConfig& spot, double dark_V, double electrons_per_V, int samplings)
    : dark_V_(dark_V), electrons_per_V_(electrons_per_V), samplings_(samplings) {
  const double s = golden::spot_sigma_px(spot);
  two_sigma2_ = 2 * s * s;
}

double CertainIntervals::fired_distance(double need_V, double signal_V, double base_V) const {
  // Largest d with S g(d) + base >= need, shrunk by the margin.
  if (base_V >= need_V) return RowCertainty::kAll;
  if (!(signal_V > 0)) return -1;
  const double g = (need_V - base_V) / signal_V;
  if (g > 1) return -1;
  return std::sqrt(two_sigma2_ * -std::log(g)) * (1 - kMargin);
}

double CertainIntervals::never_distance(double cap_V, double signal_V, double base_V) const {
  // Smallest d with S g(d) + base <= cap, grown by the margin.
  if (base_V >= cap_V) return RowCertainty::kAll;
  if (!(signal_V > 0)) return 0;
  const double g = (cap_V - base_V) / signal_V;
  if (g >= 1) return 0;
  return std::sqrt(two_sigma2_ * -std::log(g)) * (1 + kMargin);
}

void CertainIntervals::compute(double signal_V, double background_V, const ActivationBounds& b,
                               RowCertainty& out) const {
  const int N = samplings_;
  out.fired_within.resize(static_cast<std::size_t>(N));
  out.never_beyond.resize(static_cast<std::size_t>(N));
  const double base_V = background_V + dark_V_;
  for (int k = 1; k <= N; ++k) {
    // The swing at t_N (V) whose mean count by sampling k is the bound: lambda N / (k c).
    const double per_e = static_cast<double>(N) / (k * electrons_per_V_);
    double& r = out.fired_within[static_cast<std::size_t>(k - 1)];
    double& s = out.never_beyond[static_cast<std::size_t>(k - 1)];
    r = b.always_from_e < 1e300 ? fired_distance(b.always_from_e * (1 + kMargin) * per_e, signal_V, base_V) : -1;
    s = b.never_upto_e >= 0 ? never_distance(b.never_upto_e * (1 - kMargin) * per_e, signal_V, base_V)
                            : RowCertainty::kAll;
  }
  for (int k = N - 2; k >= 0; --k)
    out.fired_within[static_cast<std::size_t>(k)] =
        std::min(out.fired_within[static_cast<std::size_t>(k)], out.fired_within[static_cast<std::size_t>(k) + 1]);
  for (int k = 1; k < N; ++k)
    out.never_beyond[static_cast<std::size_t>(k)] =
        std::max(out.never_beyond[static_cast<std::size_t>(k)], out.never_beyond[static_cast<std::size_t>(k) - 1]);
}

const RowCertainty& CertainIntervals::of(double signal_V, double background_V, const ActivationBounds& b) {
  if (!have_memo_ || signal_V != memo_signal_V_ || background_V != memo_background_V_ || b.never_upto_e != memo_lo_e_ ||
      b.always_from_e != memo_hi_e_) {
    compute(signal_V, background_V, b, memo_);
    have_memo_ = true;
    memo_signal_V_ = signal_V, memo_background_V_ = background_V;
    memo_lo_e_ = b.never_upto_e, memo_hi_e_ = b.always_from_e;
  }
  return memo_;
}

}  // namespace rangesim::systemc
