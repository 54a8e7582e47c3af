#include "systemc/tof_spad/pixel_kernel.h"

#include <algorithm>
#include <cmath>

namespace rangesim::systemc::spad {

namespace {
constexpr std::uint64_t kSignalSalt = 0x5349474e414cULL, kUniformSalt = 0x554e49464fULL, kSpadSalt = 0x53504144ULL;
double exp_gap(pcg32& rng) { return -std::log(uniform_open01(rng)); }
double echo_sum(const PixelRates& r) {
  double s = 0;
  for (const SpadEcho& e : r.echoes) s += e.signal_Hz;
  return s;
}
// Largest mean drawn by one inversion: exp(-mean) stays far from underflow.
constexpr double kInversionMaxMean = 64.0;
// Poisson(mu) as the sum of ceil(mu / 64) independent Poisson(mu / pieces), each by inversion.
long long poisson_by_pieces(pcg32& rng, double mu) {
  const long long pieces = static_cast<long long>(std::ceil(mu / kInversionMaxMean));
  const double m = mu / static_cast<double>(pieces), e = std::exp(-m);
  long long total = 0;
  for (long long i = 0; i < pieces; ++i) {
    const double u = uniform_open01(rng);
    double p = e, cum = p;
    long long k = 0;
    while (cum < u && k < 100000) p *= m / static_cast<double>(++k), cum += p;
    total += k;
  }
  return total;
}
}  // namespace

SpadPixelKernel::SpadPixelKernel(const TofSpadConfig& cfg, const PixelRates& r, const SpadNoise& n,
                                 long long laser_cycles, std::uint64_t seed, std::uint64_t frame, std::uint32_t row,
                                 std::uint32_t column)
    : period_s_(1.0 / cfg.laser.repetition_rate_Hz),
      laser_cycles_(laser_cycles),
      signal_per_cycle_((r.signal_Hz + echo_sum(r)) / cfg.laser.repetition_rate_Hz),
      uniform_rate_Hz_((n.background ? r.background_Hz : 0.0) +
                       (n.dark ? cfg.spad.dark_count_rate_Hz + r.dark_extra_Hz : 0.0)),
      round_trip_s_(r.round_trip_s),
      pulse_sigma_s_(n.pulse_width ? cfg.laser.sigma_per_fwhm * cfg.laser.pulse_fwhm_s : 0.0),
      jitter_sigma_s_(cfg.spad.jitter_sigma_s),
      dead_time_s_(cfg.spad.dead_time_s),
      afterpulse_p_(cfg.spad.afterpulse_probability),
      afterpulse_tau_s_(cfg.spad.afterpulse_time_constant_s),
      jitter_on_(n.jitter),
      afterpulse_on_(n.afterpulse),
      signal_rng_(pixel_stream(pixel_stream_key(seed ^ kSignalSalt, frame, row, column))),
      uniform_rng_(pixel_stream(pixel_stream_key(seed ^ kUniformSalt, frame, row, column))),
      spad_rng_(pixel_stream(pixel_stream_key(seed ^ kSpadSalt, frame, row, column))) {
  // A photon is of each echo with its share of the rate (thinning a Poisson process): the main
  // echo below the first cumulative share, further echo k below the (k+1)-th.
  double cum = r.signal_Hz;
  const double total = r.signal_Hz + echo_sum(r);
  for (const SpadEcho& e : r.echoes) {
    if (!(total > 0)) break;
    echo_share_.push_back(cum / total);
    echo_delay_s_.push_back(e.round_trip_s);
    cum += e.signal_Hz;
  }
  next_signal_cycle();
  next_uniform();
  advance();
}

SpadTime SpadPixelKernel::shifted(SpadTime t, double dt_s) const {
  if (t.never()) return t;
  double o = t.offset_s + dt_s;
  if (o >= 0 && o < period_s_) return {t.cycle, o};
  const double k = std::floor(o / period_s_);
  // Far past any integration (a gap of a vanishing rate): never.
  if (!(std::fabs(k) < 4e18) || (k > 0 && static_cast<double>(t.cycle) + k > 4e18)) return SpadTime::never_time();
  o -= k * period_s_;
  long long c = t.cycle + static_cast<long long>(k);
  if (o < 0) o += period_s_, --c;  // rounding of k x period
  if (o >= period_s_) o -= period_s_, ++c;
  return {c, o};
}

void SpadPixelKernel::next_signal_cycle() {
  signal_buf_.clear();
  if (!(signal_per_cycle_ > 0)) return;
  // Cycles without a photon are skipped: the gap is geometric with P(photon) = 1 - exp(-mu).
  const double skip = std::floor(exp_gap(signal_rng_) / signal_per_cycle_);
  const double cycle = static_cast<double>(signal_cycle_) + 1.0 + skip;
  if (cycle >= static_cast<double>(laser_cycles_)) {
    signal_cycle_ = -2;  // exhausted
    return;
  }
  signal_cycle_ = static_cast<long long>(cycle);
  // Photon count given at least one: zero-truncated Poisson by inversion.
  const double mu = signal_per_cycle_;
  long long k = 1;
  if (mu <= kInversionMaxMean) {
    const double u = uniform_open01(signal_rng_) * -std::expm1(-mu);
    double p = std::exp(-mu) * mu, cum = p;
    while (cum < u && k < 100000) p *= mu / static_cast<double>(++k), cum += p;
  } else {
    // Far above 1 / dead time: exp(-mu) underflows past mu ~ 745 and the inversion above would
    // return its cap. A sum of Poisson(<= kInversionMaxMean) pieces is Poisson(mu) exactly; a sum
    // of 0 (probability e^-mu) is drawn again.
    do k = poisson_by_pieces(signal_rng_, mu);
    while (k == 0);
  }
  // Offsets within the photon's own cycle: the echo (possibly beyond a period) around the round trip.
  const SpadTime t0{signal_cycle_, 0.0};
  for (long long i = 0; i < k; ++i) {
    double centre = round_trip_s_;
    if (!echo_share_.empty()) {  // which echo: one more draw only when there are several
      const double u = uniform_open01(signal_rng_);
      for (size_t e = echo_share_.size(); e-- > 0;)
        if (u >= echo_share_[e]) {
          centre = echo_delay_s_[e];
          break;
        }
    }
    signal_buf_.push_back(shifted(t0, centre + pulse_sigma_s_ * standard_normal(signal_rng_)));
  }
  std::sort(signal_buf_.begin(), signal_buf_.end(), std::greater<SpadTime>());
}

void SpadPixelKernel::next_uniform() {
  if (!(uniform_rate_Hz_ > 0)) {
    uniform_next_ = SpadTime::never_time();
    return;
  }
  const SpadTime base = uniform_started_ ? uniform_next_ : SpadTime{0, 0.0};
  uniform_started_ = true;
  uniform_next_ = shifted(base, exp_gap(uniform_rng_) / uniform_rate_Hz_);
  if (uniform_next_.cycle >= laser_cycles_) uniform_rate_Hz_ = 0;  // exhausted (keep the value for peek)
}

void SpadPixelKernel::advance() {
  for (;;) {
    // Earliest pending arrival among the signal buffer, the uniform process and the afterpulses.
    const SpadTime ts = signal_buf_.empty() ? SpadTime::never_time() : signal_buf_.back();
    const SpadTime tu = uniform_next_;
    const SpadTime ta = afterpulse_q_.empty() ? SpadTime::never_time() : afterpulse_q_.top();
    const SpadTime t = std::min({ts, tu, ta});
    if (!(t.cycle < laser_cycles_)) {
      next_avalanche_ = SpadTime::never_time();
      return;
    }
    const bool is_afterpulse = (t == ta && ta < ts && ta < tu);
    if (t == ts && !is_afterpulse) {
      signal_buf_.pop_back();
      if (signal_buf_.empty() && signal_cycle_ >= 0) next_signal_cycle();
    } else if (t == tu && !is_afterpulse) {
      if (uniform_rate_Hz_ > 0)
        next_uniform();
      else
        uniform_next_ = SpadTime::never_time();
    } else {
      afterpulse_q_.pop();
    }
    ++photons_;
    if (t < dead_until_) continue;  // SPAD still recharging: lost (non-paralysable)
    if (t.cycle < 0) continue;      // pulse tail before the first START
    // Geiger avalanche: quench, dead time, maybe an afterpulse, jittered output edge.
    dead_until_ = shifted(t, dead_time_s_);
    const double u_ap = uniform_open01(spad_rng_), g_ap = exp_gap(spad_rng_), z = standard_normal(spad_rng_);
    if (afterpulse_on_ && u_ap < afterpulse_p_) afterpulse_q_.push(shifted(dead_until_, afterpulse_tau_s_ * g_ap));
    if (is_afterpulse) ++afterpulses_;
    ++avalanches_;
    next_avalanche_ = jitter_on_ ? shifted(t, jitter_sigma_s_ * z) : t;
    return;
  }
}

}  // namespace rangesim::systemc::spad
