#include "golden/tof_lockin/validity.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "golden/tof_lockin/pulse_timing.h"
#include "golden/tof_lockin/tap_charge.h"

namespace rangesim::golden {

namespace {

// Variance of one sample of tap k read as `v` volts: the noise of the charge that reading implies.
double sample_variance(const TofLockinConfig& cfg, int tap, double v, double lsb_V) {
  const double offset_V = cfg.pixel.source_follower_gain * cfg.pixel.offset_voltage_V;
  const double electrons = std::max(0.0, (v - offset_V) / volts_per_electron(cfg, tap));
  const double sigma = tap_sample(cfg, tap, electrons).sigma_V;
  return sigma * sigma + lsb_V * lsb_V / 12;
}

// a, b and their variances from the measured taps.
struct Taps {
  double value[2] = {0, 0}, var[2] = {0, 0};
};

Taps taps(const TofLockinConfig& cfg, const MeasuredTaps& t) {
  const double lsb_V = cfg.readout.adc_full_scale_V / std::ldexp(1.0, cfg.readout.adc_bits);
  const bool ambient = cfg.readout.ambient_subtraction;
  Taps r;
  for (int k = 0; k < 2; ++k) {
    r.value[k] = t.led_V[k] - cfg.readout.offset_calibration_V - (ambient ? t.ambient_V[k] : 0);
    r.var[k] = sample_variance(cfg, k, t.led_V[k], lsb_V);
    if (ambient) r.var[k] += sample_variance(cfg, k, t.ambient_V[k], lsb_V);
  }
  return r;
}

}  // namespace

double measured_snr(const TofLockinConfig& cfg, const MeasuredTaps& t) {
  const Taps r = taps(cfg, t);
  const double s = r.value[0] + r.value[1];
  return s > 0 ? s / std::sqrt(r.var[0] + r.var[1]) : 0.0;
}

double measured_range_noise_m(const TofLockinConfig& cfg, const MeasuredTaps& t) {
  const Taps r = taps(cfg, t);
  const double a = r.value[0], b = r.value[1], s = a + b;
  if (!(s > 0)) return std::numeric_limits<double>::infinity();
  return max_range_m(cfg.source) * std::sqrt(b * b * r.var[0] + a * a * r.var[1]) / (s * s);
}

bool measured_range_valid(const TofLockinConfig& cfg, const MeasuredTaps& t) {
  return measured_snr(cfg, t) >= cfg.readout.min_snr &&
         measured_range_noise_m(cfg, t) <= cfg.readout.max_range_noise_fraction * max_range_m(cfg.source);
}

}  // namespace rangesim::golden
