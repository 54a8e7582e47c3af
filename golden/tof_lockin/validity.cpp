#include "golden/tof_lockin/validity.h"

#include <algorithm>
#include <cmath>

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

}  // namespace

double measured_snr(const TofLockinConfig& cfg, const MeasuredTaps& t) {
  const double lsb_V = cfg.readout.adc_full_scale_V / std::ldexp(1.0, cfg.readout.adc_bits);
  const bool ambient = cfg.readout.ambient_subtraction;
  double s = 0, var = 0;
  for (int k = 0; k < 2; ++k) {
    s += t.led_V[k] - cfg.readout.offset_calibration_V - (ambient ? t.ambient_V[k] : 0);
    var += sample_variance(cfg, k, t.led_V[k], lsb_V);
    if (ambient) var += sample_variance(cfg, k, t.ambient_V[k], lsb_V);
  }
  return s > 0 ? s / std::sqrt(var) : 0.0;
}

}  // namespace rangesim::golden
