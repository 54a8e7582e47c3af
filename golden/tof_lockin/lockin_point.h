#pragma once
// One operating point of the tof-lockin sensor: signal photocurrent x background photocurrent at
// a target distance, through the whole data flow (pulse split -> FD charge -> ADC -> ambient
// subtraction -> eq. 2.25 -> frame averaging), with the detection verdict and the range error in
// closed form.
//
// Detection (in this order):
//   out_of_range     T_D = 2 L / c outside [0, T0]: the tap ratio no longer maps on the delay
//   saturated        the mean FD swing of a tap (signal + background + dark + V_offset) exceeds
//                    V_sat, or its ADC input exceeds the full scale (the code clips)
//   below_threshold  the light-induced V1 + V2 at the ADC input is below readout.detection_threshold_V
//                    (V_sig_min of eq. 4.11; the preset puts it at the weakest signal of Table 4.1)
//   noise_limited    the SNR of the ratio's denominator (mean of V1 + V2 - 2 V_cal over its rms)
//                    is below readout.min_snr: the denominator reaches 0 in some frames, the
//                    ratio has no usable moments and the delta method no meaning
//   range_error_unbounded
//                    the rms noise of one range value (one range map, first-order delta method,
//                    std_first_m) exceeds readout.max_range_noise_fraction x c T0 / 2: a range
//                    is derived but says little; the same criterion a range map's pixel applies
//                    to its own measured taps (validity.h)
//   detectable       otherwise
// Range error (rms over frames and, for fixed-pattern noise, over pixels), N_p frames averaged:
//   accuracy = sqrt(bias^2 + fpn_m^2 + Var_1frame / N_p)
// Mean and variance of one range value by the second-order delta method, or where the SNR of the
// denominator is below 30 integrated exactly for Gaussian taps over the frames that give a range
// (range_estimate.h: the moments a Monte Carlo of the kernels measures).
// bias = E[L] - L_true collects the deterministic parts: quantisation (truncating ADC), offset
// mis-calibration (V_cal != remaining offset), deep electrons / PHASE3 leakage (common-mode light
// charge compresses the ratio towards 1/2), the pulse's rise time and the ratio's second-order
// noise bias. Averaging N_p range images divides only the variance (independent frames).
#include <string>

#include "core/tof_lockin/config.h"

namespace rangesim::golden {

enum class LockinDetect { Detectable, BelowThreshold, NoiseLimited, RangeErrorUnbounded, Saturated, OutOfRange };
const char* to_string(LockinDetect d);

struct LockinPoint {
  LockinDetect detect = LockinDetect::Detectable;
  double distance_m = 0;      // true distance
  double delay_s = 0;         // T_D
  double signal_V = 0;        // light-induced V1 + V2 at the ADC input (mean)
  double v1_V = 0, v2_V = 0;  // mean ADC input of each tap in the LED-on frame
  double n1_e = 0, n2_e = 0;  // tap-specific signal electrons
  double mean_m = 0;          // E[L]
  double bias_m = 0;          // E[L] - distance
  double std_m = 0;           // rms noise of one frame
  double std_first_m = 0;     // first-order part of std_m (the detectability criterion's noise)
  double fpn_m = 0;           // rms over pixels of the chip's fixed pattern (golden/tof_lockin/nonideal.h)
  double accuracy_m = 0;      // sqrt(bias^2 + fpn^2 + std^2 / N_p)
  double snr = 0;             // SNR of the ratio's denominator (validity of the delta method)
};

// Full model at one point; `frames` = N_p range images averaged.
LockinPoint evaluate_point(const TofLockinConfig& cfg, double signal_A, double background_A, double distance_m,
                           long long frames);

// The signal photocurrent that gives a light-induced V1 + V2 of `signal_V` at the ADC input at
// this distance (the thesis quotes signal levels in volts).
double signal_current_for_voltage_A(const TofLockinConfig& cfg, double signal_V, double distance_m);

// ADC LSB Delta V_ADC = full scale / 2^bits.
double adc_lsb_V(const TofLockinConfig& cfg);

}  // namespace rangesim::golden
