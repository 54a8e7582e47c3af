#pragma once
// Configuration of the tof-spad sensor (thesis [11], sections 2.4 / 4.2), one struct per block.
// The same structs feed the golden model (golden/tof_spad/), and later the SystemC kernels and
// the RTL of the TDC / histogram, so the views cannot drift apart.
#include "core/nonideal.h"
#include "core/params.h"

namespace rangesim {

// Single-photon avalanche diode in Geiger mode (eq. 2.27-2.30).
struct SpadConfig {
  double pde = 0.2;                           // photon detection efficiency (rates in the preset already include it)
  double fill_factor = 0.06;                  // active area / pixel area
  double dark_count_rate_Hz = 100.0;          // dark counts, uniform in time, on top of the background
  double dead_time_s = 50e-9;                 // non-paralysable dead time after an avalanche
  double afterpulse_probability = 0.01;       // afterpulses per avalanche
  double afterpulse_time_constant_s = 20e-9;  // exponential delay of afterpulses after the dead time
  double jitter_sigma_s = 60e-12;             // SPAD + front-end timing jitter, rms
};

// Pulsed laser: Gaussian pulse, one TDC START per pulse (eq. 2.31).
struct SpadLaserConfig {
  double wavelength_m = 635e-9;                 // laser wavelength
  double pulse_fwhm_s = 100e-12;                // FWHM of the pulse
  double sigma_per_fwhm = 0.42466090014400953;  // sigma / FWHM (thesis: 0.45)
  double repetition_rate_Hz = 40e6;             // pulses per second; period = unambiguous window
};

// Column time-to-digital converter shared by several columns.
struct TdcConfig {
  double lsb_s = 97.65625e-12;           // nominal bin width
  int bits = 10;                         // codes 0 .. 2^bits - 1
  double full_range_s = 100e-9;          // hits later than this after START are lost
  double dnl_rms_lsb = 0.1;              // random per-bin width error, rms
  double inl_rms_lsb = 0.3;              // smooth bow of the bin edges, rms over the used codes
  long long nonlinearity_seed = 1;       // seed of the deterministic DNL pattern
  int columns_per_tdc = 4;               // columns sharing one TDC; first hit among them wins
  double neighbour_rate_fraction = 1.0;  // rate of each sharing neighbour / ours (1 = flat scene)
  double busy_time_s = 100e-9;           // conversion + transfer: the TDC takes no hit meanwhile
};

// Histogram and reconstruction (eq. 2.34 / 4.19 with the correct normalisation).
struct SpadHistogramConfig {
  double integration_time_s = 50e-3;    // acquisition time of one histogram
  int peak_window_bins = 7;             // PW: bins around the peak used by the centroid
  bool coates_correction = true;        // pile-up correction before the centroid
  bool subtract_background = true;      // subtract the per-bin background estimated outside PW
  double readout_word_rate_Hz = 100e6;  // histogram words read out per second per output lane
};

// Evaluation grid and the criteria that make a point "detectable".
struct SpadEvaluationConfig {
  double signal_min_Hz = 100, signal_max_Hz = 1e6;  // signal count-rate axis
  int signal_points = 41;
  double background_min_Hz = 10, background_max_Hz = 1e8;  // ambient count-rate axis
  int background_points = 71;
  int frames_averaged = 1;                            // histograms accumulated per range value
  double distance_m = 3.6;                            // distance of the grid's accuracy
  double distance_min_m = 0.8, distance_max_m = 3.6;  // distance sweep
  int distance_points = 29;
  double detection_sigma = 5.0;        // k: window signal counts must exceed k sqrt(background counts)
  double min_signal_counts = 10.0;     // and at least this many signal counts in the window
  double min_armed_fraction = 0.01;    // below: the TDC is stopped before the echo (pile-up saturated)
  double reference_signal_Hz = 300.0;  // conditions of the published figures
  double reference_background_Hz = 10.0;
  double sweep_signal_Hz = 1e5;  // fixed signal of the accuracy-vs-background sweep
};

// The array and the camera lens (scene radiometry and scene sizes).
struct SpadArrayConfig {
  int rows = 128, columns = 128;
  double pitch_m = 25e-6;
  double focal_length_m = 8e-3;
  double f_number = 1.4;
};

struct TofSpadConfig {
  SpadArrayConfig array;
  SpadConfig spad;
  SpadLaserConfig laser;
  TdcConfig tdc;
  SpadHistogramConfig histogram;
  SpadEvaluationConfig evaluation;
  FixedPatternConfig fixed_pattern;  // PRNU (the PDE's spread), DSNU (the dark count rate's, Hz): core/nonideal.h
  DarkTemperatureConfig dark;        // spad.dark_count_rate_Hz is already scaled to temperature_K
  BlurConfig blur;                   // the lens's point spread and the pixels' crosstalk (scenes)
  MultipathConfig multipath;         // a second return of every echo
  double temperature_K = 300;        // the sensor's
};

// Builds the config from a validated preset; throws UserError on cross-key inconsistencies
// (full range beyond 2^bits LSB, grid min > max), naming the file and keys.
TofSpadConfig tof_spad_from_params(const ParamSet& params);

// Derived integers, one formula each (golden, the kernels and the RTL harnesses use these):
// laser cycles (TDC STARTs) per row integration, round(T_int f_rep);
long long laser_cycles_per_row(const TofSpadConfig& cfg);
// the TDC clock (one LSB per cycle) and the clock cycles per histogram word read out,
// ceil(f_clk / word rate) less a rounding guard so an exact ratio is not rounded up.
double tdc_clock_Hz(const TofSpadConfig& cfg);
long long cycles_per_histogram_word(const TofSpadConfig& cfg);

// The sensor's radiometry from a validated preset (core/radiometry.h, core/tof_spad/radiometry.cpp).
struct SensorRadiometry;
SensorRadiometry tof_spad_radiometry(const ParamSet& params);

}  // namespace rangesim
