#pragma once
// Configuration of the tof-lockin sensor (thesis [12], sections 2.3 and 4.1), one struct per
// block along the data flow: light pulse -> lock-in gates (PHASE1/2/3) -> photogate pixel with two
// floating diffusions -> column ADC -> range reconstruction (eq. 2.25 / 4.9) -> frame averaging.
// The same structs feed the golden model, the SystemC kernels and the RTL parameters. Names carry
// a Lockin prefix where a plain name (PixelConfig) is already taken by another sensor.
#include <cmath>

#include "core/nonideal.h"
#include "core/params.h"

namespace rangesim {

// Photogate pixel with transfer gates TX1/TX2 to FD1/FD2 and drain gates TXD (thesis Fig. 2.8-2.11).
struct LockinPixelConfig {
  int columns = 336;                  // pixels per row
  int rows = 252;                     // rows
  double pitch_m = 15e-6;             // pixel pitch
  double fd1_capacitance_F = 10e-15;  // C1: FD1 collects N1 through TX1 (PHASE1)
  double fd2_capacitance_F = 10e-15;  // C2: FD2 collects N2 through TX2 (PHASE2)
  double source_follower_gain = 1.0;  // A_sf: ADC input = A_sf x FD swing
  double saturation_voltage_V = 1.5;  // FD swing at which a tap saturates
  double offset_voltage_V = 0.02;     // constant offset on each FD present in every frame (eq. 2.25)
  double charge_separation = 1.0;     // fraction of signal electrons reaching the tap open at generation;
                                      // the rest (deep electrons) arrive uniformly over the period
  double drain_efficiency = 1.0;      // fraction of PHASE3 electrons drained; the rest splits over FD1/FD2
  double fill_factor = 0.3;           // photosensitive area / pixel area (scene radiometry)
  double responsivity_A_per_W = 0.4;  // photocurrent per optical watt at the source wavelength (scene radiometry)
};

// The camera lens (scene radiometry: optical power on a pixel).
struct LockinOpticsConfig {
  double focal_length_m = 8e-3;
  double f_number = 1.4;
};

// Pulsed LED source (trapezoid of FWHM T0 and linear 0-100% ramps of rise_time / 0.8).
struct LightPulseConfig {
  double wavelength_m = 870e-9;   // LED wavelength (documentation only in the golden model)
  double pulse_width_s = 100e-9;  // T0 = TX1 and TX2 open time
  double duty_cycle = 0.1;        // repetition period = T0 / duty
  double rise_time_s = 0.0;       // 10-90 % rise and fall time (0 = rectangular)
};

// Lock-in gate timing: PHASE1 (TX1, T0), PHASE2 (TX2, T0), PHASE3 (TXD, rest of the period).
struct LockinGateConfig {
  double clock_Hz = 100e6;                 // gate-pulse generator clock (edges on its grid)
  long long accumulations_per_frame = 50;  // N_acc charge-transfer cycles summed on the FDs per frame
};

// Column ADC, reconstruction and frame schedule.
struct LockinReadoutConfig {
  int adc_bits = 12;                    // codes 0 .. 2^bits - 1
  double adc_full_scale_V = 1.5;        // LSB Delta V_ADC = full scale / 2^bits (eq. 4.9)
  double detection_threshold_V = 5e-3;  // smallest light-induced V1 + V2 accepted as a range value
  double min_snr = 3.0;                 // smallest mean / rms of the ratio's denominator accepted
  // Largest rms noise of one range value (one range map, delta method) as a fraction of c T0 / 2
  // for which it counts as a range: golden's detectability and the range maps' validity.
  double max_range_noise_fraction = 0.05;
  bool cds_enabled = false;         // true: FD kTC reset noise cancelled
  bool ambient_subtraction = true;  // true: a frame with the LED off is read and subtracted per tap
  double offset_calibration_V =
      0.0;                 // V_offset subtracted from each tap in eq. 2.25 after (optional) ambient subtraction
  double clock_Hz = 36e6;  // readout clock
  long long adc_conversion_cycles = 4096;  // cycles of one column-parallel conversion
  long long output_cycles_per_row = 672;   // cycles to shift one converted row out
};

// Noise sources: shot, kTC at reset, read, dark, optional fixed pattern.
struct LockinNoiseConfig {
  double temperature_K = 300.0;      // kTC reset noise temperature
  double dark_current_A = 1e-15;     // dark current into each FD during the accumulation
  double read_noise_V = 0.7e-3;      // SF + ADC input noise per sample, rms, at the ADC input
  double fixed_pattern_rms_V = 0.0;  // pixel-to-pixel offset spread, rms (cancelled by ambient subtraction)
};

// Evaluation grid and reference conditions (thesis Table 4.1, Fig. 4.4-4.6).
struct LockinEvaluationConfig {
  double signal_min_A = 1e-11;  // signal photocurrent during the light pulse
  double signal_max_A = 1.5e-9;
  int signal_points = 45;
  double background_min_A = 1e-14;  // background photocurrent (constant)
  double background_max_A = 1e-8;
  int background_points = 121;
  long long frames_averaged = 1;  // N_p range images averaged
  double distance_m = 1.0;        // reference distance of the grid evaluation
  double distance_min_m = 0.8;    // distance sweep
  double distance_max_m = 12.0;
  int distance_points = 45;
};

// Non-idealities (core/nonideal.h; docs/model-limits.md): the chip's fixed pattern (PRNU of the
// photogate, DSNU of each FD's dark current in A, tap gain mismatch), the point spread and
// crosstalk, a second return, and the Poisson statistics of the offset charge.
struct LockinNonidealConfig {
  FixedPatternConfig fixed_pattern;
  BlurConfig blur;
  MultipathConfig multipath;
  DarkTemperatureConfig dark;     // noise.dark_current_A is already scaled to noise.temperature_K
  bool offset_shot_noise = true;  // the offset charge V_offset C / q on each FD is Poisson
};

// How the clock-level model draws its noise (docs/tof-lockin-clock.md, "Fidelity knobs"); both
// switches change cost only, never the law of what is drawn.
struct LockinSimulationConfig {
  bool merged_draws = true;   // aggregated frames: one Poisson per tap (frame + offset charge), one
                              // normal (kTC + read) where V_sat cannot be reached (frame_draw.h)
  bool direct_trials = true;  // evaluate --trials: each trial's frames drawn without stepping the
                              // frame schedule (the same draws as the kernel, bit for bit)
  bool code_tables = true;    // evaluate --trials, from a point's 65536th trial on: each tap's ADC code
                              // drawn from its exact law where V_sat cannot be reached (code_law.h)
};

struct TofLockinConfig {
  LockinPixelConfig pixel;
  LockinOpticsConfig optics;
  LightPulseConfig source;
  LockinGateConfig gates;
  LockinReadoutConfig readout;
  LockinNoiseConfig noise;
  LockinEvaluationConfig eval;
  LockinNonidealConfig nonideal;
  LockinSimulationConfig simulation;
};

// Builds the config from a validated preset; throws UserError naming file and keys on cross-key
// inconsistencies (rise time longer than the pulse, grid min > max, T0 off the gate clock grid).
TofLockinConfig tof_lockin_from_params(const ParamSet& params);

// Derived integers, computed here only: T0 and the repetition period T_rep = T0 / duty in
// gate-clock cycles (rounded; the config and the gate generator kernel require whole numbers).
inline long long gate_t0_cycles(const TofLockinConfig& c) {
  return std::llround(c.source.pulse_width_s * c.gates.clock_Hz);
}
inline long long gate_period_cycles(const TofLockinConfig& c) {
  return std::llround(c.source.pulse_width_s / c.source.duty_cycle * c.gates.clock_Hz);
}

// The sensor's radiometry from a validated preset (core/radiometry.h, core/tof_lockin/radiometry.cpp).
struct SensorRadiometry;
SensorRadiometry tof_lockin_radiometry(const ParamSet& params);

}  // namespace rangesim
