#pragma once
// Configuration of the ls-demodulation sensor (thesis [27], sections 2.2 and 3.2, Table 3.2), one
// struct per block along the data flow: photodiode -> current copier with LPF background
// subtraction -> log I-V converter -> two correlating integrators -> comparator -> position
// readout -> triangulation. The spot and triangulation geometry are shared with ls-conventional
// (SpotConfig, OpticsConfig), as is the light-section position readout.
#include "core/ls_conventional/config.h"
#include "core/nonideal.h"
#include "core/params.h"

namespace rangesim {

// Pixel array and the correlation (integration) window of one decision.
struct DemodPixelConfig {
  int columns = 120;                  // pixels per row (position-detection direction)
  int rows = 110;                     // rows read out per frame
  double pitch_m = 45e-6;             // pixel pitch
  double integration_time_s = 50e-6;  // correlation window T of one decision (= cycles / f0)
  double fill_factor = 0.3;           // photosensitive area / pixel area (scene radiometry)
  double responsivity_A_per_W = 0.4;  // photocurrent per optical watt at the source wavelength (scene radiometry)
};

// Beam modulation and MPY+/MPY- reference (thesis Fig. 2.7).
struct ModulationConfig {
  double frequency_Hz = 100e3;       // correlation frequency f0
  double source_duty_cycle = 0.5;    // fraction of each period the beam is on
  double reference_phase_rad = 0.0;  // phase of the MPY+ start after the beam-on edge
};

// Current copier and LPF background subtraction (eq. 2.8-2.10).
struct SuppressionConfig {
  double mirror_gain = 1.0;             // alpha
  double mirror_mismatch = 0.01;        // alpha' / alpha - 1 (the I_pd copy against the I_avg copy)
  double lpf_time_constant_s = 1.2e-3;  // tau of the LPF forming I_avg
};

// Logarithmic I-V converter (eq. 2.11): V_mod = beta slope ln(max(I_offset + I_mod, I_leak) / I_offset).
struct LogConverterConfig {
  double gain = 1.0;                 // beta
  double slope_V = 0.0336;           // volts per e-fold of current (n kT / q)
  double offset_current_A = 1e-9;    // I_offset: the log converter's bias, V_mod = 0 at I_mod = 0
  double leakage_current_A = 1e-15;  // floor of I_offset + I_mod (swings below are clipped)
};

// Two correlating integrators switched by MPY+ / MPY- (eq. 2.13).
struct CorrelatorConfig {
  double capacitance_plus_F = 37e-15;   // C1 (MPY+)
  double capacitance_minus_F = 37e-15;  // C2 (MPY-)
  double transconductance_S = 60e-9;    // g_m: V_mod integrates as g_m V_mod / C
  double reference_duty_cycle = 0.5;    // fraction of each period MPY+ is active
  int cycles = 5;                       // N correlation periods per decision
  double saturation_voltage_V = 2.0;    // |swing| of each integrator before it saturates
};

// Comparator (eq. 2.12).
struct DemodComparatorConfig {
  double threshold_V = 0.01;           // V_cmp on V_out+ - V_out-
  int adc_bits = 1;                    // only 1 bit is modelled (Table 3.2)
  double false_activation_max = 0.01;  // tolerated P(background alone activates a pixel of the row)
};

// Noise: shot, kTC at reset, read, dark, optional fixed pattern.
struct DemodNoiseConfig {
  double temperature_K = 300.0;      // kTC on C1 and C2, sampled at each integrator reset
  double dark_current_A = 1e-15;     // adds to I_dc, with its shot noise
  double read_noise_V = 0.33e-3;     // source-follower / comparator noise on the difference, rms; static over a frame
  double fixed_pattern_rms_V = 0.0;  // comparator offset spread, rms (treated as per-decision noise, see docs)
};

// Position readout clock schedule (frame rate).
struct DemodReadoutConfig {
  double clock_Hz = 10e6;
  int row_cycles = 41;  // cycles to read one row and encode its position
  int address_bits = 7;
};

// Evaluation grid over signal x background photocurrent, and the averaging knobs.
struct DemodGridConfig {
  double signal_min_A = 7.4e-13;
  double signal_max_A = 1.11e-9;
  int signal_points = 65;
  double background_min_A = 1e-13;
  double background_max_A = 1e-6;
  int background_points = 141;
  int subpixel_points = 16;           // spot positions across one pixel for the accuracy average
  int frames_averaged = 1;            // N_p frames per range value
  int detections = 1;                 // K correlation decisions per frame, their centres averaged
  double sweep_background_A = 1e-10;  // background of the one-dimensional accuracy sweeps
};

struct LsDemodulationConfig {
  DemodPixelConfig pixel;
  ModulationConfig modulation;
  SuppressionConfig suppression;
  LogConverterConfig log_converter;
  CorrelatorConfig correlator;
  DemodComparatorConfig comparator;
  DemodNoiseConfig noise;
  SpotConfig spot;
  DemodReadoutConfig readout;
  OpticsConfig optics;          // distance_m: where accuracy_m is taken
  double distance_min_m = 0.8;  // evaluation distance span (Table 3.2)
  double distance_max_m = 1.2;
  DemodGridConfig grid;
  double min_detecting_fraction = 0;  // a row's range counts when this fraction of the decisions found the spot
  double edge_margin_px = 1.5;        // ... and its centre lies this far inside the first and last column
  FixedPatternConfig fixed_pattern;   // PRNU, DSNU (A), comparator offset per pixel (core/nonideal.h)
  BlurConfig blur;                    // point spread and crosstalk of the scene runs
  DarkTemperatureConfig dark;         // noise.dark_current_A is already scaled to noise.temperature_K
};

// Builds the config from a validated preset; throws UserError on cross-key inconsistencies
// (cycles / f0 against the integration time, address bits, grid order), naming file and keys.
LsDemodulationConfig ls_demodulation_from_params(const ParamSet& params);

// Derived: the chain-settle cycles of one row's readout, S = row_cycles - 1 - 2 address_bits
// (search start, settle, the two streamed edge addresses; systemc/ls_demodulation/sensor_kernel.h
// and the RTL's SEARCH_CYCLES). Below 1 the row cannot be read in row_cycles.
int readout_search_cycles(const DemodReadoutConfig& readout);

// The sensor's radiometry from a validated preset (core/radiometry.h, core/ls_demodulation/radiometry.cpp).
struct SensorRadiometry;
SensorRadiometry ls_demodulation_radiometry(const ParamSet& params);

}  // namespace rangesim
