#include "systemc/tof_spad/spad_pixel_kernel.h"

#include <algorithm>
#include <cmath>

namespace rangesim::systemc::spad {

namespace {
constexpr std::uint64_t kSignalSalt = 0x5349474e414cULL, kUniformSalt = 0x554e49464fULL, kSpadSalt = 0x53504144ULL;
double exp_gap(pcg32& rng) { return -std::log(uniform_open01(rng)); }
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

SpadPixelKernel::SpadPixelKernel(const TofSpadConfig& cfg, const PixelRates& r, const SpadNoise& n, long long laser_cycles,
                                 std::uint64_t seed, std::uint64_t frame, std::uint32_t row, std::uint32_t column)
    : period_s_(1.0 / cfg.laser.repetition_rate_Hz),
      end_s_(static_cast<double>(laser_cycles) / cfg.laser.repetition_rate_Hz),
      signal_per_cycle_(r.signal_Hz / cfg.laser.repetition_rate_Hz),
      uniform_rate_Hz_((n.background ? r.background_Hz : 0.0) + (n.dark ? cfg.spad.dark_count_rate_Hz : 0.0)),
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
  next_signal_cycle();
  next_uniform();
  advance();
}

void SpadPixelKernel::next_signal_cycle() {
  signal_buf_.clear();
  if (!(signal_per_cycle_ > 0)) return;
  // Cycles without a photon are skipped: the gap is geometric with P(photon) = 1 - exp(-mu).
  const double skip = std::floor(exp_gap(signal_rng_) / signal_per_cycle_);
  const double cycle = static_cast<double>(signal_cycle_) + 1.0 + skip;
  if (cycle * period_s_ >= end_s_) {
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
    do k = poisson_by_pieces(signal_rng_, mu); while (k == 0);
  }
  const double t0 = static_cast<double>(signal_cycle_) * period_s_ + round_trip_s_;
  for (long long i = 0; i < k; ++i) signal_buf_.push_back(t0 + pulse_sigma_s_ * standard_normal(signal_rng_));
  std::sort(signal_buf_.begin(), signal_buf_.end(), std::greater<double>());
}

void SpadPixelKernel::next_uniform() {
  if (!(uniform_rate_Hz_ > 0)) {
    uniform_next_s_ = kNever;
    return;
  }
  const double base = uniform_next_s_ == kNever ? 0.0 : uniform_next_s_;
  uniform_next_s_ = base + exp_gap(uniform_rng_) / uniform_rate_Hz_;
  if (uniform_next_s_ >= end_s_) uniform_rate_Hz_ = 0;  // exhausted (keep the value for peek)
}

void SpadPixelKernel::advance() {
  for (;;) {
    // Earliest pending arrival among the signal buffer, the uniform process and the afterpulses.
    const double ts = signal_buf_.empty() ? kNever : signal_buf_.back();
    const double tu = uniform_next_s_;
    const double ta = afterpulse_q_.empty() ? kNever : afterpulse_q_.top();
    const double t = std::min({ts, tu, ta});
    if (!(t < end_s_)) {
      next_avalanche_s_ = kNever;
      return;
    }
    const bool is_afterpulse = (t == ta && ta < ts && ta < tu);
    if (t == ts && !is_afterpulse) {
      signal_buf_.pop_back();
      if (signal_buf_.empty() && signal_cycle_ >= 0) next_signal_cycle();
    } else if (t == tu && !is_afterpulse) {
      if (uniform_rate_Hz_ > 0) next_uniform(); else uniform_next_s_ = kNever;
    } else {
      afterpulse_q_.pop();
    }
    ++photons_;
    if (t < dead_until_s_) continue;  // SPAD still recharging: lost (non-paralysable)
    if (t < 0) continue;              // pulse tail before the first START
    // Geiger avalanche: quench, dead time, maybe an afterpulse, jittered output edge.
    dead_until_s_ = t + dead_time_s_;
    const double u_ap = uniform_open01(spad_rng_), g_ap = exp_gap(spad_rng_), z = standard_normal(spad_rng_);
    if (afterpulse_on_ && u_ap < afterpulse_p_) afterpulse_q_.push(dead_until_s_ + afterpulse_tau_s_ * g_ap);
    if (is_afterpulse) ++afterpulses_;
    ++avalanches_;
    next_avalanche_s_ = t + (jitter_on_ ? jitter_sigma_s_ * z : 0.0);
    return;
  }
}

}  // namespace rangesim::systemc::spad
