#include "golden/ls_demodulation/selectivity.h"

#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>

#include "golden/ls_demodulation/front_end.h"

namespace rangesim::golden {

double harmonic_gain_V_per_A(const LsDemodulationConfig& cfg, double background_A, int k) {
  using cd = std::complex<double>;
  const auto& s = cfg.suppression;
  const auto& lg = cfg.log_converter;
  const double I = background_A + cfg.noise.dark_current_A;
  const double I_op = lg.offset_current_A + s.mirror_gain * s.mirror_mismatch * I;
  if (!(I_op > lg.leakage_current_A)) return 0;  // clipped: no small-signal path
  const double w0 = 2 * M_PI * cfg.modulation.frequency_Hz, wk = k * w0;
  const cd H = s.mirror_gain * ((1 + s.mirror_mismatch) - 1.0 / cd(1, wk * s.lpf_time_constant_s));
  // int over one period of w(t) e^{j wk t}, piecewise constant weight.
  cd c = 0;
  double t = 0;
  for (const Segment& seg : pixel_segments(cfg, 0.0, background_A)) {
    const double C = seg.branch > 0 ? cfg.correlator.capacitance_plus_F : cfg.correlator.capacitance_minus_F;
    const cd e = (std::exp(cd(0, wk * (t + seg.duration_s))) - std::exp(cd(0, wk * t))) / cd(0, wk);
    c += (seg.branch / C) * e;
    t += seg.duration_s;
  }
  return cfg.correlator.cycles * cfg.correlator.transconductance_S * lg.gain * lg.slope_V / I_op * std::abs(H) *
         std::abs(c);
}

double harmonic_selectivity_dB(const LsDemodulationConfig& cfg, double background_A, int k) {
  const double g1 = harmonic_gain_V_per_A(cfg, background_A, 1), gk = harmonic_gain_V_per_A(cfg, background_A, k);
  // Rounding leaves ~1e-16 of g1 where the coefficient is exactly zero: report -inf there.
  if (!(gk > 1e-12 * g1)) return -std::numeric_limits<double>::infinity();
  return 20 * std::log10(gk / g1);
}

double harmonic_selectivity_square_dB(const LsDemodulationConfig& cfg, double background_A, double amplitude_A, int k) {
  const double dc = background_A + cfg.noise.dark_current_A;
  const int N = cfg.correlator.cycles;
  const double base = correlate_periodic(cfg, period_segments(cfg, dc, {}), N).diff_V;
  auto worst = [&](int h) {
    double m = 0;
    for (int d = 0; d < 32; ++d) {
      const SquareComponent sq{amplitude_A, h, 0.5, d / 32.0};
      m = std::max(m, std::fabs(correlate_periodic(cfg, period_segments(cfg, dc, {sq}), N).diff_V - base));
    }
    return m;
  };
  const double r1 = worst(1), rk = worst(k);
  if (!(rk > 1e-12 * r1)) return -std::numeric_limits<double>::infinity();
  return 20 * std::log10(rk / r1);
}

double duty_for_even_harmonic_dB(double dB) { return std::acos(std::pow(10.0, dB / 20)) / M_PI; }

double step_residual_fraction(const LsDemodulationConfig& cfg, double time_s) {
  return std::exp(-time_s / cfg.suppression.lpf_time_constant_s);
}

double step_settling_time_s(const LsDemodulationConfig& cfg, double fraction) {
  return cfg.suppression.lpf_time_constant_s * std::log(1 / fraction);
}

double step_correlator_error_V(const LsDemodulationConfig& cfg, double from_A, double to_A, double delay_s) {
  const double d = cfg.noise.dark_current_A;
  const auto seg = period_segments(cfg, to_A + d, {});
  const double start = (to_A + d) + (from_A - to_A) * std::exp(-delay_s / cfg.suppression.lpf_time_constant_s);
  const int N = cfg.correlator.cycles;
  return correlate_from(cfg, seg, N, start).diff_V - correlate_periodic(cfg, seg, N).diff_V;
}

}  // namespace rangesim::golden
