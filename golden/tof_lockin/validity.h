#pragma once
// Whether one measured pixel of a tof-lockin range map holds a usable range, from the pixel's own
// tap values: the noise is the golden per-sample noise (tap_charge.h: shot, kTC, read) at the
// electrons the measured voltages imply, plus the ADC's uniform quantisation error, for every
// sample that enters a and b (the LED frame and, with ambient subtraction, the ambient frame).
// Two figures, each with the rule golden's detectability applies to the expected values
// (lockin_point.h), so a map and the evaluate grid draw the same lines:
//   - the SNR of the ratio's denominator a + b (eq. 2.25), against readout.min_snr;
//   - the rms noise of the range value, K sqrt(b^2 v_a + a^2 v_b) / (a + b)^2 (the first-order
//     delta method at the measured a, b), against readout.max_range_noise_fraction x K, K = c T0 / 2.
#include "core/tof_lockin/config.h"

namespace rangesim::golden {

// The taps of one pixel as read: LED frame values (V at the ADC input, as value_V of the codes)
// and the ambient frame's (ignored without ambient subtraction).
struct MeasuredTaps {
  double led_V[2] = {0, 0};
  double ambient_V[2] = {0, 0};
};

// (a + b) / rms(a + b); 0 when a + b <= 0.
double measured_snr(const TofLockinConfig& cfg, const MeasuredTaps& t);

// The range value's rms noise (delta method) from the measured taps, m; +inf when a + b <= 0.
double measured_range_noise_m(const TofLockinConfig& cfg, const MeasuredTaps& t);

// Both rules: SNR >= readout.min_snr and noise <= readout.max_range_noise_fraction x c T0 / 2.
bool measured_range_valid(const TofLockinConfig& cfg, const MeasuredTaps& t);

}  // namespace rangesim::golden
