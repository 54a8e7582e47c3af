#pragma once
// Comparator threshold and the N-bit quantiser of one sampling (thesis eq. 3.5, 3.7, 3.11).
//
// All voltages here are at the comparator input, i.e. after the source follower (A_sf * swing).
//
// Threshold theta (V_cmp of eq. 3.5):
//   tracking: theta = A_sf (V_bg + V_dark) + Delta V_ADC. Eq. 3.11 says V_sig_min = Delta V_ADC +
//             V_bg: the reference follows the level the pixels reach without signal. That level
//             includes the dark current (the reference is derived from the pixels themselves), so
//             the smallest detectable signal is exactly Delta V_ADC / A_sf whatever the dark
//             current; this is what makes the quoted 0.01 V lower edge (43.5 dB) come out.
//   fixed:    theta = fixed_threshold_V.
//
// N-bit code (adc_bits = b): c = clamp(floor((v_out - ref) / LSB), 0, 2^b - 1) with
// LSB = Delta V_ADC (threshold_above_background_V) and ref = theta - LSB, so code >= m exactly when
// v_out >= theta + (m - 1) LSB, and b = 1 reproduces the comparator (code 1 iff v_out >= theta).
#include "core/ls_conventional/config.h"

namespace rangesim::golden {

struct Quantiser {
  int bits = 1;            // adc_bits
  int max_code = 1;        // 2^bits - 1
  double threshold_V = 0;  // theta: code >= 1 from here (comparator input, volts)
  double lsb_V = 0;        // Delta V_ADC
  double ref_V = 0;        // theta - LSB
};

// Comparator threshold theta at the comparator input for a background swing V_bg.
double comparator_threshold_V(const LsConventionalConfig& cfg, double background_V);

Quantiser make_quantiser(const LsConventionalConfig& cfg, double background_V);

// Comparator-input voltage at which the code reaches m (1 <= m <= max_code): theta + (m-1) LSB.
double code_threshold_V(const Quantiser& q, int m);

// Code of a comparator-input voltage (eq. 3.7 with the clamp of a real converter).
int quantise(const Quantiser& q, double output_V);

}  // namespace rangesim::golden
