#include "golden/ls_demodulation/front_end.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/physics.h"

namespace rangesim::golden {
namespace {

// 8-point Gauss-Legendre on [-1, 1]: exact for polynomials of degree 15; ln(c0 + c1 e^{-s/tau})
// over a panel of <= 2 tau is that smooth (its nearest singularity lies ~pi tau off the real axis, or just
// beyond a clip point, where the floor takes over).
constexpr double kGlX[4] = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267, 0.9602898564975363};
constexpr double kGlW[4] = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745, 0.1012285362903763};

double frac(double x) { return x - std::floor(x); }

// Adds int_{u0}^{u1} of ln(f/ref) and 1/f for f(s) = c0 + c1 e^{-s/tau} (f > 0 there).
//  - 1/f in closed form: int ds / f = (tau / c0) (s / tau + ln f) (when c0 is not tiny against c1).
//  - ln f: if f has a real zero s_z (c1 / c0 < 0), f = c0 (1 - e^{-x}), x = (s - s_z) / tau, and
//    ln f = ln|c0| + ln|x| + ln h(x), h(x) = (1 - e^{-x}) / x > 0: the log singularity next to a
//    clip point is integrated exactly (x ln|x| - x) and Gauss-Legendre sees only the smooth ln h.
//  - ln(f / ref) as log1p((d0 + c1 e^{-s/tau}) / ref), d0 = c0 - ref given exactly by the caller:
//    ln of a ratio next to 1 (a weak signal on the converter's offset current) otherwise keeps
//    only ref / |f - ref| x 1e-16 of its value.
//  - f at an end of the piece is at least the floor: an end at the clip point has f = floor
//    exactly, where rounding of c0 + c1 e^{-s/tau} (a difference of two large terms) gave 0 or
//    less and ln(f(u1) / f(u0)) an infinite or NaN shot-noise kernel.
void gauss_legendre(double c0, double c1, double tau, double u0, double u1, double ref, double d0, double floor_A,
                    LogIntegral& r) {
  if (!(u1 > u0)) return;
  auto f = [&](double s) { return c0 + c1 * std::exp(-s / tau); };
  // Past s_flat the exponential term is below e^{-41.5} ~ 1e-18 of c0: f = c0 to rounding. A
  // piece of many tau (fast LPF, slow modulation) is a head of panels plus this flat tail:
  // 8 nodes cannot resolve e^{-s/tau} over L >> tau, and the zero branch's x ln|x| and ln h
  // terms would cancel to nothing there (the integral came out wrong by its own size).
  if (c0 > 0 && c1 != 0) {
    const double s_flat = tau * (std::log(std::fabs(c1) / c0) + 41.5);
    if (s_flat < u1) {
      const double from = std::max(u0, s_flat), len = u1 - from;
      r.ln_s += len * std::log1p(d0 / ref);
      r.inv_s_per_A += len / c0;
      u1 = from;
      if (!(u1 > u0)) return;
    }
  }
  // The exact x ln|x| split only where the log singularity is within a tau of the piece; farther
  // away ln|x| + ln h(x) = ln(1 - e^{-x}) is a small difference of large terms (1e-7 errors seen
  // between a segment and its clock ticks), and log1p below is smooth and exact.
  const double sz = c0 != 0 && -c1 / c0 > 0 ? tau * std::log(-c1 / c0) : 0;
  const bool zero = c0 != 0 && -c1 / c0 > 0 && (u0 - sz) / tau < 1;
  auto h = [](double x) { return x == 0 ? 1.0 : -std::expm1(-x) / x; };
  const double ln_c0 = c0 > 0 ? std::log1p(d0 / ref) : std::log(std::fabs(c0) / ref);
  // Panels of at most 2 tau: the integrand's nearest complex singularity is >= ~pi tau away.
  const int panels = static_cast<int>(std::clamp(std::ceil((u1 - u0) / (2 * tau)), 1.0, 64.0));
  const double half = 0.5 * (u1 - u0) / panels;
  double ln = 0, inv = 0;
  for (int p = 0; p < panels; ++p) {
    const double mid = u0 + (2 * p + 1) * half;
    for (int i = 0; i < 4; ++i)
      for (double sgn : {-1.0, 1.0}) {
        const double s = mid + sgn * half * kGlX[i];
        ln += kGlW[i] * (zero ? ln_c0 + std::log(h((s - sz) / tau)) : std::log1p((d0 + c1 * std::exp(-s / tau)) / ref));
        inv += kGlW[i] / f(s);
      }
  }
  r.ln_s += half * ln;
  if (zero) {
    auto F = [](double x) { return x == 0 ? 0.0 : x * std::log(std::fabs(x)) - x; };
    r.ln_s += tau * (F((u1 - sz) / tau) - F((u0 - sz) / tau));
  }
  if (std::fabs(c0) > 1e-3 * std::fabs(c1))
    r.inv_s_per_A += tau / c0 * ((u1 - u0) / tau + std::log(std::max(f(u1), floor_A) / std::max(f(u0), floor_A)));
  else
    r.inv_s_per_A += half * inv;
}

}  // namespace

LogIntegral log_integral(double c0, double c1, double tau, double L, double floor_A, double ref, double d0) {
  LogIntegral r;
  if (std::isnan(d0)) d0 = c0 - ref;
  const double f0 = c0 + c1, fL = c0 + c1 * std::exp(-L / tau);
  const bool clip0 = f0 <= floor_A, clipL = fL <= floor_A;
  auto clipped = [&](double len) {
    r.ln_s += len * std::log(floor_A / ref);
    r.clipped_s += len;
  };
  if (clip0 && clipL) {  // f is monotone: clipped throughout
    clipped(L);
  } else if (!clip0 && !clipL) {
    gauss_legendre(c0, c1, tau, 0, L, ref, d0, floor_A, r);
  } else {
    // f crosses the floor once, at c0 + c1 e^{-s/tau} = floor.
    const double s_star = std::clamp(-tau * std::log((floor_A - c0) / c1), 0.0, L);
    if (clip0) {
      clipped(s_star);
      gauss_legendre(c0, c1, tau, s_star, L, ref, d0, floor_A, r);
    } else {
      gauss_legendre(c0, c1, tau, 0, s_star, ref, d0, floor_A, r);
      clipped(L - s_star);
    }
  }
  return r;
}

std::vector<Segment> period_segments(const LsDemodulationConfig& cfg, double dc_A,
                                     const std::vector<SquareComponent>& comps) {
  const double T0 = 1.0 / cfg.modulation.frequency_Hz;
  const double ref0 = frac(cfg.modulation.reference_phase_rad / (2 * M_PI));
  const double Dr = cfg.correlator.reference_duty_cycle;
  // Edges as fractions of the period.
  std::vector<double> e{0.0, ref0, frac(ref0 + Dr)};
  for (const auto& c : comps)
    for (int m = 0; m < c.harmonic; ++m) {
      e.push_back(frac((m + c.delay_periods) / c.harmonic));
      e.push_back(frac((m + c.delay_periods + c.duty) / c.harmonic));
    }
  std::sort(e.begin(), e.end());
  e.erase(std::unique(e.begin(), e.end(), [](double a, double b) { return b - a < 1e-12; }), e.end());
  e.push_back(1.0);
  std::vector<Segment> seg;
  for (size_t i = 0; i + 1 < e.size(); ++i) {
    const double len = e[i + 1] - e[i];
    if (len < 1e-12) continue;
    const double t = 0.5 * (e[i] + e[i + 1]);  // midpoint decides which levels are on
    double ac = 0;
    for (const auto& c : comps)
      if (frac(t * c.harmonic - c.delay_periods) < c.duty) ac += c.amplitude_A;
    seg.push_back({len * T0, dc_A + ac, frac(t - ref0) < Dr ? +1 : -1, dc_A, ac});
  }
  return seg;
}

std::vector<Segment> pixel_segments(const LsDemodulationConfig& cfg, double beam_A, double background_A) {
  return period_segments(cfg, background_A + cfg.noise.dark_current_A,
                         {SquareComponent{beam_A, 1, cfg.modulation.source_duty_cycle, 0.0}});
}

double lpf_offset_after_A(const LsDemodulationConfig& cfg, double x, const Segment& s, double dc0, double L) {
  const double target = (s.dc_A - dc0) + s.ac_A;
  return target + (x - target) * std::exp(-L / cfg.suppression.lpf_time_constant_s);
}

double lpf_periodic_offset_A(const LsDemodulationConfig& cfg, const std::vector<Segment>& period) {
  if (period.empty()) return 0;
  const double dc0 = period.front().dc_A;
  double b = 0, T0 = 0;  // the offset after one period from 0
  for (const auto& s : period) {
    b = lpf_offset_after_A(cfg, b, s, dc0, s.duration_s);
    T0 += s.duration_s;
  }
  return b / -std::expm1(-T0 / cfg.suppression.lpf_time_constant_s);
}

double lpf_periodic_start_A(const LsDemodulationConfig& cfg, const std::vector<Segment>& period) {
  return period.empty() ? 0 : period.front().dc_A + lpf_periodic_offset_A(cfg, period);
}

namespace {

// The log stage's integral over one segment with the LPF at offset x from dc0 at its start.
LogIntegral segment_log_integral(const LsDemodulationConfig& cfg, const Segment& s, double x, double dc0, double L) {
  const auto& lg = cfg.log_converter;
  const double alpha = cfg.suppression.mirror_gain, eps = cfg.suppression.mirror_mismatch;
  const double I = s.photocurrent_A;
  // I_off + I_mod = c0 + c1 e^{-s/tau}: c0 its limit, c1 = -alpha (I_avg - I_pd) the LPF's lag.
  return log_integral(lg.offset_current_A + alpha * eps * I, -alpha * lpf_lag_A(x, s, dc0),
                      cfg.suppression.lpf_time_constant_s, L, lg.leakage_current_A, lg.offset_current_A,
                      alpha * eps * I);
}

double gain_V(const LsDemodulationConfig& cfg) {  // g_m beta s
  return cfg.correlator.transconductance_S * cfg.log_converter.gain * cfg.log_converter.slope_V;
}

double capacitance_F(const LsDemodulationConfig& cfg, int branch) {
  return branch > 0 ? cfg.correlator.capacitance_plus_F : cfg.correlator.capacitance_minus_F;
}

// Shot-noise variance of one segment [a, b] with G = G(b): K(u) = alpha (1+eps) k - alpha G(u) =
// A + B e^{-(b-u)/tau}, A = alpha eps k, B = alpha (k - G(b)); G becomes G(a).
double segment_var(double q_I, double k, double alpha, double eps, double tau, double L, double& G) {
  const double e1 = -std::expm1(-L / tau), e2 = -std::expm1(-2 * L / tau);
  const double A = alpha * eps * k, B = alpha * (k - G);
  G = k * e1 + G * (1 - e1);
  return q_I * (A * A * L + 2 * A * B * tau * e1 + B * B * 0.5 * tau * e2);
}

// Adds the shot-noise variance of the segments k[0..] (period repeated), walked backwards from
// G(T) = G_end, and of the shot noise before the window, to `out`.
void add_shot_var_backwards(const LsDemodulationConfig& cfg, const std::vector<Segment>& period,
                            const std::vector<double>& k, double G_end, double past_mean_A, CorrelatorOutput& out) {
  const double alpha = cfg.suppression.mirror_gain, eps = cfg.suppression.mirror_mismatch;
  const double tau = cfg.suppression.lpf_time_constant_s, q = phys::kElementaryCharge_C;
  const size_t S = period.size();
  double G = G_end;
  for (size_t jj = k.size(); jj-- > 0;) {
    const Segment& s = period[jj % S];
    (s.branch > 0 ? out.shot_var_plus_V2 : out.shot_var_minus_V2) +=
        segment_var(q * s.photocurrent_A, k[jj], alpha, eps, tau, s.duration_s, G);
  }
  out.shot_var_past_V2 = past_shot_var_V2(cfg, past_mean_A, G);
  out.shot_var_V2 = out.shot_var_plus_V2 + out.shot_var_minus_V2 + out.shot_var_past_V2;
}

CorrelatorOutput run(const LsDemodulationConfig& cfg, const std::vector<Segment>& period, int periods, double start_A,
                     double past_mean_A) {
  const size_t S = period.size(), n = S * static_cast<size_t>(std::max(periods, 0));
  std::vector<double> k(n);  // noise kernel per segment, V / (A s) per A of i_mod
  CorrelatorOutput out;
  const double dc0 = S ? period.front().dc_A : 0;
  double x = start_A - dc0, T = 0;  // the LPF as its offset from dc0
  for (size_t j = 0; j < n; ++j) {
    const Segment& s = period[j % S];
    const double L = s.duration_s;
    const LogIntegral li = segment_log_integral(cfg, s, x, dc0, L);
    const double C = capacitance_F(cfg, s.branch);
    (s.branch > 0 ? out.plus_V : out.minus_V) += gain_V(cfg) / C * li.ln_s;
    k[j] = s.branch * gain_V(cfg) / C * li.inv_s_per_A / L;
    out.peak_abs_V = std::max({out.peak_abs_V, std::fabs(out.plus_V), std::fabs(out.minus_V)});
    out.clipped_fraction += li.clipped_s;
    x = lpf_offset_after_A(cfg, x, s, dc0, L);
    T += L;
  }
  out.diff_V = out.plus_V - out.minus_V;
  out.clipped_fraction = T > 0 ? out.clipped_fraction / T : 0;
  out.lpf_end_A = dc0 + x;

  // Shot noise, backwards: G(u) = int_u^T k(t) e^{-(t-u)/tau} dt / tau.
  add_shot_var_backwards(cfg, period, k, 0.0, past_mean_A, out);
  return out;
}

}  // namespace

double past_shot_var_V2(const LsDemodulationConfig& cfg, double past_mean_A, double G) {
  // Before the window only the LPF path sees the noise: K(u) = -alpha G(0) e^{u/tau}, u < 0.
  const double alpha = cfg.suppression.mirror_gain;
  return phys::kElementaryCharge_C * past_mean_A * alpha * alpha * G * G * 0.5 * cfg.suppression.lpf_time_constant_s;
}

std::vector<double> period_noise_kernel(const LsDemodulationConfig& cfg, const std::vector<Segment>& period, double x) {
  std::vector<double> k(period.size());
  const double dc0 = period.empty() ? 0 : period.front().dc_A;
  for (size_t j = 0; j < period.size(); ++j) {
    const Segment& s = period[j];
    const LogIntegral li = segment_log_integral(cfg, s, x, dc0, s.duration_s);
    k[j] = s.branch * gain_V(cfg) / capacitance_F(cfg, s.branch) * li.inv_s_per_A / s.duration_s;
    x = lpf_offset_after_A(cfg, x, s, dc0, s.duration_s);
  }
  return k;
}

// Periodic steady state: every period repeats the first, so the window is aggregated exactly in
// O(S log N) time and O(S + log N) memory (correlator.cycles goes to 1e9: the segment-by-segment
// loop needed 3N doubles and N x S steps). Means: N x one period. Shot noise: one period of the
// backward recursion is an affine map of G (at the period's end -> at its start) and adds a
// quadratic in G to the variance; N periods are that map composed N times (binary powering).
PeriodicShotNoise::PeriodicShotNoise(const LsDemodulationConfig& cfg, const std::vector<Segment>& period,
                                     std::vector<double> k, long long periods)
    : period_(period),
      k_(std::move(k)),
      alpha_(cfg.suppression.mirror_gain),
      eps_(cfg.suppression.mirror_mismatch),
      tau_(cfg.suppression.lpf_time_constant_s) {
  const double q = phys::kElementaryCharge_C;
  Map one;  // one period backwards, with G_j = a + c G_end at each segment's end
  for (size_t jj = period_.size(); jj-- > 0;) {
    const Segment& s = period_[jj];
    const double L = s.duration_s, e1 = -std::expm1(-L / tau_), e2 = -std::expm1(-2 * L / tau_);
    const double A = alpha_ * eps_ * k_[jj], b0 = alpha_ * (k_[jj] - one.a), b1 = -alpha_ * one.c;  // B = b0 + b1 G_end
    const double w = q * s.photocurrent_A;
    const int br = s.branch > 0 ? 0 : 1;
    one.v0[br] += w * (A * A * L + 2 * A * b0 * tau_ * e1 + b0 * b0 * 0.5 * tau_ * e2);
    one.v1[br] += w * (2 * A * b1 * tau_ * e1 + b0 * b1 * tau_ * e2);
    one.v2[br] += w * b1 * b1 * 0.5 * tau_ * e2;
    one.a = k_[jj] * e1 + one.a * (1 - e1);
    one.c *= 1 - e1;
  }
  pow2_.push_back(one);
  for (long long n = std::max(periods, 1LL); n > 1; n >>= 1) pow2_.push_back(compose(pow2_.back(), pow2_.back()));
}

// `later` (closer to the window end) first, then `earlier`.
PeriodicShotNoise::Map PeriodicShotNoise::compose(const Map& later, const Map& earlier) {
  Map m;
  m.a = earlier.a + earlier.c * later.a;
  m.c = earlier.c * later.c;
  for (int b = 0; b < 2; ++b) {
    m.v0[b] = later.v0[b] + earlier.v0[b] + earlier.v1[b] * later.a + earlier.v2[b] * later.a * later.a;
    m.v1[b] = later.v1[b] + earlier.v1[b] * later.c + 2 * earlier.v2[b] * later.a * later.c;
    m.v2[b] = later.v2[b] + earlier.v2[b] * later.c * later.c;
  }
  return m;
}

PeriodicShotNoise::Map PeriodicShotNoise::power(long long n) const {
  Map acc;  // identity
  for (size_t i = 0; n > 0; n >>= 1, ++i) {
    if (i >= pow2_.size()) throw std::logic_error("PeriodicShotNoise: more periods than built for");
    if (n & 1) acc = compose(acc, pow2_[i]);
  }
  return acc;
}

double PeriodicShotNoise::g_end(long long after) const { return power(after).a; }

double PeriodicShotNoise::segment_var_V2(std::size_t j, double& G) const {
  return segment_var(phys::kElementaryCharge_C * period_[j].photocurrent_A, k_[j], alpha_, eps_, tau_,
                     period_[j].duration_s, G);
}

PeriodicShotNoise::Window PeriodicShotNoise::window(long long periods) const {
  const Map m = power(periods);  // G = 0 at the window end
  return {std::max(0.0, m.v0[0]), std::max(0.0, m.v0[1]), m.a};
}

namespace {

CorrelatorOutput run_periodic(const LsDemodulationConfig& cfg, const std::vector<Segment>& period, int periods,
                              double past_mean_A) {
  const size_t S = period.size();
  const double N = std::max(periods, 0);
  CorrelatorOutput out;
  std::vector<double> dplus(S), dminus(S);
  const double dc0 = S ? period.front().dc_A : 0;
  const double x0 = lpf_periodic_offset_A(cfg, period);
  double x = x0, T = 0, plus = 0, minus = 0;
  for (size_t j = 0; j < S; ++j) {
    const Segment& s = period[j];
    const LogIntegral li = segment_log_integral(cfg, s, x, dc0, s.duration_s);
    (s.branch > 0 ? plus : minus) += gain_V(cfg) / capacitance_F(cfg, s.branch) * li.ln_s;
    dplus[j] = plus, dminus[j] = minus;  // swings at the end of segment j of the first period
    out.clipped_fraction += li.clipped_s;
    x = lpf_offset_after_A(cfg, x, s, dc0, s.duration_s);
    T += s.duration_s;
  }
  if (periods <= 0) return out;
  out.plus_V = N * plus, out.minus_V = N * minus;
  out.diff_V = out.plus_V - out.minus_V;
  // |swing| is convex along the periods at a fixed segment: the first or the last period peaks.
  for (size_t j = 0; j < S; ++j)
    out.peak_abs_V = std::max({out.peak_abs_V, std::fabs(dplus[j]), std::fabs(dminus[j]),
                               std::fabs((N - 1) * plus + dplus[j]), std::fabs((N - 1) * minus + dminus[j])});
  out.clipped_fraction = T > 0 ? out.clipped_fraction / T : 0;
  out.lpf_end_A = dc0 + x;
  const PeriodicShotNoise noise(cfg, period, period_noise_kernel(cfg, period, x0), periods);
  const PeriodicShotNoise::Window w = noise.window(periods);
  out.shot_var_plus_V2 = w.plus_V2;
  out.shot_var_minus_V2 = w.minus_V2;
  out.shot_var_past_V2 = past_shot_var_V2(cfg, past_mean_A, w.g_start);
  out.shot_var_V2 = out.shot_var_plus_V2 + out.shot_var_minus_V2 + out.shot_var_past_V2;
  return out;
}

double mean_current_A(const std::vector<Segment>& period) {
  double q = 0, T = 0;
  for (const auto& s : period) q += s.photocurrent_A * s.duration_s, T += s.duration_s;
  return T > 0 ? q / T : 0;
}

}  // namespace

CorrelatorOutput correlate_periodic(const LsDemodulationConfig& cfg, const std::vector<Segment>& period, int periods) {
  return run_periodic(cfg, period, periods, mean_current_A(period));
}

CorrelatorOutput correlate_stepped(const LsDemodulationConfig& cfg, const std::vector<Segment>& period, int periods,
                                   double lpf_start_A) {
  return run(cfg, period, periods, lpf_start_A, lpf_start_A);
}

// Transient periods stepped (their noise kernels kept: O(M S)), then the N - M identical periods
// in the periodic state aggregated (PeriodicShotNoise), their G at the start continued backwards
// through the stepped ones. M: the periods until the LPF's distance from its periodic state,
// |x - x_ss| e^{-m T0 / tau}, is below 1e-17 of the currents (rounding of the periodic state).
CorrelatorOutput correlate_from(const LsDemodulationConfig& cfg, const std::vector<Segment>& period, int periods,
                                double lpf_start_A) {
  const size_t S = period.size();
  if (S == 0 || periods <= 0) return run(cfg, period, periods, lpf_start_A, lpf_start_A);
  const double tau = cfg.suppression.lpf_time_constant_s, dc0 = period.front().dc_A;
  const double x_ss = lpf_periodic_offset_A(cfg, period), x0 = lpf_start_A - dc0;
  double T0 = 0, ref = std::fabs(x_ss);
  for (const auto& s : period) T0 += s.duration_s, ref = std::max(ref, std::fabs((s.dc_A - dc0) + s.ac_A));
  const double gap = std::fabs(x0 - x_ss);
  const double m = gap > 1e-17 * ref ? std::ceil(tau / T0 * std::log(gap / (1e-17 * std::max(ref, 1e-300)))) : 0.0;
  const long long M = static_cast<long long>(std::min<double>(m, periods));
  if (M >= periods) return run(cfg, period, periods, lpf_start_A, lpf_start_A);
  const long long R = periods - M;
  CorrelatorOutput out;
  std::vector<double> k(static_cast<size_t>(M) * S);
  double x = x0, T = 0, clipped = 0;
  for (size_t j = 0; j < k.size(); ++j) {  // the transient, segment by segment
    const Segment& s = period[j % S];
    const LogIntegral li = segment_log_integral(cfg, s, x, dc0, s.duration_s);
    const double C = capacitance_F(cfg, s.branch);
    (s.branch > 0 ? out.plus_V : out.minus_V) += gain_V(cfg) / C * li.ln_s;
    k[j] = s.branch * gain_V(cfg) / C * li.inv_s_per_A / s.duration_s;
    out.peak_abs_V = std::max({out.peak_abs_V, std::fabs(out.plus_V), std::fabs(out.minus_V)});
    clipped += li.clipped_s;
    x = lpf_offset_after_A(cfg, x, s, dc0, s.duration_s);
    T += s.duration_s;
  }
  // The R periodic periods: N x one period as in correlate_periodic, after the transient's swings.
  const CorrelatorOutput p = run_periodic(cfg, period, 1, 0.0);
  const double Rd = static_cast<double>(R);
  double plus1 = 0, minus1 = 0;  // swing at the end of each segment of one periodic period
  std::vector<double> dplus(S), dminus(S);
  {
    double xs = x_ss;
    for (size_t j = 0; j < S; ++j) {
      const Segment& s = period[j];
      const LogIntegral li = segment_log_integral(cfg, s, xs, dc0, s.duration_s);
      (s.branch > 0 ? plus1 : minus1) += gain_V(cfg) / capacitance_F(cfg, s.branch) * li.ln_s;
      dplus[j] = plus1, dminus[j] = minus1;
      xs = lpf_offset_after_A(cfg, xs, s, dc0, s.duration_s);
    }
  }
  for (size_t j = 0; j < S; ++j)  // convex along the periods: the first or the last peaks
    out.peak_abs_V = std::max({out.peak_abs_V, std::fabs(out.plus_V + dplus[j]), std::fabs(out.minus_V + dminus[j]),
                               std::fabs(out.plus_V + (Rd - 1) * plus1 + dplus[j]),
                               std::fabs(out.minus_V + (Rd - 1) * minus1 + dminus[j])});
  out.plus_V += Rd * plus1, out.minus_V += Rd * minus1;
  out.diff_V = out.plus_V - out.minus_V;
  out.clipped_fraction = (clipped + Rd * p.clipped_fraction * T0) / (T + Rd * T0);
  out.lpf_end_A = p.lpf_end_A;
  // Noise: the periodic part's variance and G at its start, then backwards through the transient.
  const PeriodicShotNoise noise(cfg, period, period_noise_kernel(cfg, period, x_ss), R);
  const PeriodicShotNoise::Window w = noise.window(R);
  out.shot_var_plus_V2 = w.plus_V2, out.shot_var_minus_V2 = w.minus_V2;
  add_shot_var_backwards(cfg, period, k, w.g_start, lpf_start_A, out);
  return out;
}

double ktc_variance_V2(const LsDemodulationConfig& cfg) {
  const double kT = phys::kBoltzmann_J_per_K * cfg.noise.temperature_K;
  return kT / cfg.correlator.capacitance_plus_F + kT / cfg.correlator.capacitance_minus_F;
}

}  // namespace rangesim::golden
