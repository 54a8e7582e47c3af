#include "golden/tof_lockin/lockin_point.h"

#include <algorithm>
#include <cmath>

#include "golden/common/threshold.h"
#include "golden/tof_lockin/adc_moments.h"
#include "golden/tof_lockin/nonideal.h"
#include "golden/tof_lockin/pulse_timing.h"
#include "golden/tof_lockin/range_estimate.h"
#include "golden/tof_lockin/tap_charge.h"

namespace rangesim::golden {

namespace {

// Light-induced V1 + V2 at the ADC input (tap-specific signal and common-mode light charge).
double light_voltage_V(const TofLockinConfig& cfg, const FrameCharge& c) {
  return volts_per_electron(cfg, 0) * (c.signal_e[0] + c.light_common_e) +
         volts_per_electron(cfg, 1) * (c.signal_e[1] + c.light_common_e);
}

// Below this SNR of a + b the ratio's moments are integrated (range_moments_given_range) instead of
// expanded: there the expansion's next terms, O(SNR^-4), reach 1e-6 relative.
constexpr double kIntegrateBelowSnr = 30;

// The smallest a + b the reconstruction accepts (the kernel's rule: a + b > 0 and >=
// detection_threshold_V, systemc/tof_lockin/sensor_kernel.h) as a continuous edge: a + b lies on
// the lattice j lsb - 2 V_cal of the codes, so the edge is half a step below the first value taken.
double range_threshold_V(const TofLockinConfig& cfg, double lsb) {
  const double off = 2.0 * cfg.readout.offset_calibration_V;
  const double j_thr = std::ceil((cfg.readout.detection_threshold_V * (1.0 - 1e-9) + off) / lsb);
  const double j_pos = std::floor(off / lsb) + 1.0;
  return std::max(j_thr, j_pos) * lsb - off - lsb / 2.0;
}

}  // namespace

const char* to_string(LockinDetect d) {
  switch (d) {
    case LockinDetect::Detectable: return "detectable";
    case LockinDetect::BelowThreshold: return "below_threshold";
    case LockinDetect::NoiseLimited: return "noise_limited";
    case LockinDetect::RangeErrorUnbounded: return "range_error_unbounded";
    case LockinDetect::Saturated: return "saturated";
    case LockinDetect::OutOfRange: return "out_of_range";
  }
  return "?";
}

double adc_lsb_V(const TofLockinConfig& cfg) {
  return cfg.readout.adc_full_scale_V / std::ldexp(1.0, cfg.readout.adc_bits);
}

double signal_current_for_voltage_A(const TofLockinConfig& cfg, double signal_V, double distance_m) {
  // The light-induced voltage is linear in I_s: scale the voltage of 1 A.
  const FrameCharge c = frame_charge(cfg, 1.0, 0.0, round_trip_delay_s(distance_m));
  return signal_V / light_voltage_V(cfg, c);
}

LockinPoint evaluate_point(const TofLockinConfig& cfg, double signal_A, double background_A, double distance_m,
                           long long frames) {
  LockinPoint pt;
  pt.distance_m = distance_m;
  pt.delay_s = round_trip_delay_s(distance_m);
  if (!delay_in_range(cfg.source, pt.delay_s)) {
    pt.detect = LockinDetect::OutOfRange;
    return pt;
  }
  const FrameCharge c = scene_frame_charge(cfg, signal_A, background_A, pt.delay_s);
  const TapSample on[2] = {tap_sample(cfg, 0, c.total_e(0)), tap_sample(cfg, 1, c.total_e(1))};
  const TapSample off[2] = {tap_sample(cfg, 0, c.ambient_e()), tap_sample(cfg, 1, c.ambient_e())};
  pt.v1_V = on[0].mean_V, pt.v2_V = on[1].mean_V;
  pt.n1_e = c.signal_e[0], pt.n2_e = c.signal_e[1];
  pt.signal_V = light_voltage_V(cfg, c);
  if (tap_saturates(cfg, on[0]) || tap_saturates(cfg, on[1])) {
    pt.detect = LockinDetect::Saturated;
    return pt;
  }
  // Up to rounding: the preset's lowest signal is defined exactly at the threshold.
  if (below_threshold(pt.signal_V, cfg.readout.detection_threshold_V)) {
    pt.detect = LockinDetect::BelowThreshold;
    return pt;
  }

  // Digitised tap values: LED frame minus (optionally) the ambient frame minus V_cal.
  const double lsb = adc_lsb_V(cfg);
  const long long codes = 1LL << cfg.readout.adc_bits;
  double mu[2], var[2];
  for (int k = 0; k < 2; ++k) {
    const QuantisedMoments qon = quantised_moments(on[k].mean_V, on[k].sigma_V, lsb, codes);
    mu[k] = qon.mean_V - cfg.readout.offset_calibration_V;
    var[k] = qon.var_V2;
    if (cfg.readout.ambient_subtraction) {
      const QuantisedMoments qoff = quantised_moments(off[k].mean_V, off[k].sigma_V, lsb, codes);
      mu[k] -= qoff.mean_V;
      var[k] += qoff.var_V2;
    }
  }
  if (!(mu[0] + mu[1] > 0.0)) {  // nothing left of the signal after the reconstruction
    pt.detect = LockinDetect::BelowThreshold;
    return pt;
  }
  const double K = max_range_m(cfg.source);
  RangeMoments m = range_moments(K, mu[0], var[0], mu[1], var[1]);
  if (m.snr < kIntegrateBelowSnr)
    m = range_moments_given_range(K, mu[0], var[0], mu[1], var[1], range_threshold_V(cfg, lsb));
  pt.mean_m = m.mean_m;
  pt.bias_m = m.mean_m - distance_m;
  pt.std_m = std::sqrt(m.var_m2);
  pt.std_first_m = std::sqrt(m.var_first_m2);
  pt.snr = m.snr;
  if (m.snr < cfg.readout.min_snr) {
    pt.detect = LockinDetect::NoiseLimited;
    return pt;
  }
  // The criterion a range map's pixel applies to its own taps (validity.h): one range value's rms
  // noise, to first order, against a fraction of the unambiguous range.
  if (pt.std_first_m > cfg.readout.max_range_noise_fraction * K) {
    pt.detect = LockinDetect::RangeErrorUnbounded;
    return pt;
  }
  // The chip's fixed pattern (golden/tof_lockin/nonideal.h): the same every frame, so not divided by N_p.
  pt.fpn_m = fixed_pattern_range_m(cfg, c, mu[0], mu[1]);
  const double n_p = static_cast<double>(frames < 1 ? 1 : frames);
  pt.accuracy_m = std::sqrt(pt.bias_m * pt.bias_m + pt.fpn_m * pt.fpn_m + m.var_m2 / n_p);
  return pt;
}

}  // namespace rangesim::golden
