#pragma once
// Configuration of the ls-conventional sensor (thesis [31]), one struct per block. The same
// structs feed the golden model (arguments), the SystemC kernels (constructors) and the RTL
// (Verilog parameters), so the three views cannot drift apart.
#include "core/nonideal.h"
#include "core/params.h"

namespace rangesim {

// Photodiode pixel with source follower (thesis eq. 3.1-3.4).
struct PixelConfig {
  double integration_time_s = 50e-6;    // photo-integration time t
  double pd_capacitance_F = 40e-15;     // well capacity C_pd
  double source_follower_gain = 1.0;    // A_sf
  double saturation_voltage_V = 1.741;  // swing at which the pixel saturates
  double dark_current_A = 1e-15;        // dark current at temperature_K (adds to the photocurrent, with its shot noise)
  double temperature_K = 300.0;         // for the kTC reset noise
  double read_noise_V = 0.0;            // per-frame input-referred SF/comparator noise, rms
  int columns = 375;                    // pixels per row
  int rows = 365;                       // rows searched in parallel
  double pitch_m = 11.25e-6;            // pixel pitch
  double fill_factor = 0.5;             // photosensitive area / pixel area (scene radiometry only)
  double responsivity_A_per_W = 0.4;    // photodiode responsivity (scene radiometry only)
};

// Gaussian sheet-beam profile across a row (eq. 3.6).
struct SpotConfig {
  double fwhm_px = 3.0;                         // full width at half maximum
  double sigma_per_fwhm = 0.42466090014400953;  // sigma / FWHM
};

enum class ThresholdMode { Tracking, Fixed };

// In-pixel comparator, or an N-bit quantiser per sampling (eq. 3.5, 3.7, 3.11).
struct ComparatorConfig {
  ThresholdMode threshold_mode = ThresholdMode::Tracking;  // V_cmp referred to background or absolute
  double threshold_above_background_V = 0.01;              // tracking: V_cmp = V_bg + this (Delta V_ADC)
  double fixed_threshold_V = 0.011;                        // fixed: V_cmp
  int adc_bits = 1;                                        // 1 = comparator; N: codes 0..2^N-1 of LSB Delta V_ADC
  double false_activation_max = 0.01;                      // tolerated P(background alone activates a row pixel)
};

// Samplings during one integration, at t_k = k T / N (k = 1..N).
struct MultiSamplingConfig {
  int samplings = 4;
};

// Row-parallel chained search with bit-streamed column addresses (also the RTL parameters).
struct AddressSearchConfig {
  int columns = 375;               // pixels in the searched row
  int address_bits = 9;            // width of a streamed column address
  int addresses_per_sampling = 2;  // left and right edge of the activated run
};

// Clock schedule of one frame access (see golden/common/frame_timing.h for the formula).
struct FrameTimingConfig {
  double clock_Hz = 39.45e6;
  int reset_cycles = 4;
  int latch_cycles = 1;
  int search_cycles = 2;
  int address_bits = 9;
  int addresses_per_sampling = 2;
  int output_cycles = 12;
  int beam_positions = 375;
};

// Triangulation geometry (thesis eq. 1.1-1.8).
struct OpticsConfig {
  double focal_length_m = 10e-3;
  double baseline_m = 73.6e-3;
  double distance_m = 1.1;
  double f_number = 1.4;  // lens F# (scene radiometry only)
};

// Log-spaced evaluation grid over signal x background.
struct EvaluationGridConfig {
  double signal_min_V = 1e-3;
  double signal_max_V = 1.5;
  int signal_points = 61;
  double background_min_V = 1e-3;
  double background_max_V = 1.0;
  int background_points = 61;
  int subpixel_points = 16;           // spot positions of the fixed midpoint rule (subpixel_tolerance = 0)
  double subpixel_tolerance = 0.001;  // estimated relative error of the adaptive average (1-bit ADC); 0: the fixed rule
};

// When a row's range counts in a range map (systemc/ls_conventional/simulate.cpp).
struct LsValidityConfig {
  double min_detecting_fraction = 0;  // of the samplings that found the spot; 0: any one
  double edge_margin_px = 1.5;        // the centre this far inside the first and last column
};

// How the clock-level model draws its noise (systemc/ls_conventional/activation_sampler.h).
struct LsSimulationConfig {
  bool exact_activation_sampling = true;  // first firing sampling drawn exactly, certain pixels not drawn
  bool certain_intervals = true;          // exact, sparse: a row's certain pixels found as intervals, not one by one
  bool inversion_draw = true;             // exact: an uncertain pixel's first firing by inversion, one uniform
};

struct LsConventionalConfig {
  PixelConfig pixel;
  SpotConfig spot;
  ComparatorConfig comparator;
  MultiSamplingConfig multisampling;
  AddressSearchConfig search;
  FrameTimingConfig timing;
  OpticsConfig optics;
  EvaluationGridConfig grid;
  LsValidityConfig validity;
  LsSimulationConfig simulation;
  DarkTemperatureConfig dark;        // pixel.dark_current_A is already scaled to pixel.temperature_K
  FixedPatternConfig fixed_pattern;  // PRNU, DSNU (A), comparator offset per pixel (core/nonideal.h)
  BlurConfig blur;                   // point spread and crosstalk of the scene runs (across rows and columns)
};

// The clock schedule of one frame access, one formula each (golden/ls_conventional/frame_timing,
// the multi-sampling sequencer kernel and the RTL harnesses use these): one sampling is a latch,
// the search settle and the streamed addresses; a frame access is the reset, N samplings and the
// centre output.
long long sampling_cycles(const FrameTimingConfig& timing);
long long frame_cycles(const FrameTimingConfig& timing, int samplings);

// Builds the config from a validated preset; throws UserError on cross-key inconsistencies
// (e.g. address_bits too narrow for columns), naming the file and keys.
LsConventionalConfig ls_conventional_from_params(const ParamSet& params);

// The sensor's radiometry from a validated preset (core/radiometry.h, core/ls_conventional/radiometry.cpp).
struct SensorRadiometry;
SensorRadiometry ls_conventional_radiometry(const ParamSet& params);

}  // namespace rangesim
