#pragma once
// Whether one measured pixel of a tof-lockin range map holds a usable range: the SNR of the ratio's
// denominator a + b (eq. 2.25), the light-induced V1 + V2, measured from the pixel's own tap
// values. The noise is the golden per-sample noise (tap_charge.h: shot, kTC, read) at the
// electrons the measured voltages imply, plus the ADC's uniform quantisation error, for every
// sample that enters a and b (the LED frame and, with ambient subtraction, the ambient frame).
// The pixel is valid at readout.min_snr, the rule golden's detectability uses on the expected
// values (lockin_point.h), so a map and the evaluate grid draw the same line.
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

}  // namespace rangesim::golden
