// Schema of presets/tof-spad.toml (thesis [11], section 2.4 / 4.2, Table 4.2).
// Data flow: pulsed laser -> SPAD (PDE, dark counts, dead time, afterpulsing, jitter; eq. 2.27-
// 2.33) -> column TDC shared by several columns (LSB, range, DNL/INL, busy time) -> per-pixel
// histogram over the integration time -> pile-up (Coates) correction -> centroid over the peak
// window PW (eq. 2.34 / 4.19) -> distance.
#include "core/tof_spad/config.h"
#include "core/nonideal.h"
#include "core/schemas.h"
#include "core/sensor_registry.h"

namespace rangesim {

const ParamSchema& tof_spad_schema() {
  using K = ParamKind;
  static const ParamSchema base{
      "tof-spad",
      {
          // Pixel array.
          {"array.columns", K::Integer, "", 1, 4096, false, "pixels per row"},
          {"array.rows", K::Integer, "", 1, 4096, false, "rows (one row is connected to the column TDCs at a time)"},
          {"array.pitch_m", K::Real, "m", 0, 1e-3, true, "pixel pitch"},
          {"optics.focal_length_m", K::Real, "m", 0, 10, true, "lens focal length (radiometry: field of view)"},
          {"optics.f_number", K::Real, "", 0.5, 64, false, "lens F# (radiometry of physical scenes and axes)"},
          // Single-photon avalanche diode.
          {"spad.pde", K::Real, "", 0, 1, true,
           "photon detection efficiency at the laser wavelength (per photon on the active area)"},
          {"spad.fill_factor", K::Real, "", 0, 1, true, "active area / pixel area"},
          {"spad.dark_count_rate_Hz", K::Real, "Hz", 0, 1e9, false,
           "dark count rate (thermal and tunnelling triggers) at dark.reference_temperature_K, scaled to "
           "spad.temperature_K"},
          {"spad.dead_time_s", K::Real, "s", 0, 1e-3, true, "dead time after each avalanche (non-paralysable)"},
          {"spad.afterpulse_probability", K::Real, "", 0, 1, false,
           "probability that an avalanche is followed by an afterpulse"},
          {"spad.afterpulse_time_constant_s", K::Real, "s", 0, 1e-3, true,
           "exponential delay constant of afterpulses after the dead time"},
          {"spad.jitter_sigma_s", K::Real, "s", 0, 1e-6, false,
           "SPAD + front-end timing jitter, rms (IRF sigma without the laser pulse)"},
          // Pulsed laser.
          {"laser.wavelength_m", K::Real, "m", 0, 1e-5, true, "laser wavelength"},
          {"laser.pulse_fwhm_s", K::Real, "s", 0, 1e-6, true, "FWHM of the Gaussian laser pulse (eq. 2.31)"},
          {"laser.sigma_per_fwhm", K::Real, "", 0, 1, true, "sigma / FWHM (exact Gaussian 0.4247; thesis writes 0.45)"},
          {"laser.repetition_rate_Hz", K::Real, "Hz", 0, 10e9, true,
           "pulse repetition rate (one TDC START per pulse); unambiguous range c / (2 f)"},
          // Column time-to-digital converters.
          {"tdc.lsb_s", K::Real, "s", 0, 1e-6, true, "TDC resolution (one LSB)"},
          {"tdc.bits", K::Integer, "", 1, 24, false, "TDC output bits"},
          {"tdc.full_range_s", K::Real, "s", 0, 1, true,
           "conversion window after START; later hits are lost (<= LSB x 2^bits)"},
          {"tdc.dnl_rms_lsb", K::Real, "LSB", 0, 1, false, "differential nonlinearity, rms over codes"},
          {"tdc.inl_rms_lsb", K::Real, "LSB", 0, 100, false, "integral nonlinearity, rms over codes"},
          {"tdc.nonlinearity_seed", K::Integer, "", 0, 9007199254740991.0, false,
           "seed of the deterministic per-bin DNL pattern"},
          {"tdc.columns_per_tdc", K::Integer, "", 1, 4096, false,
           "columns sharing one TDC (first hit among them wins)"},
          {"tdc.neighbour_rate_fraction", K::Real, "", 0, 1, false,
           "count rate of each sharing neighbour relative to ours (1 = flat scene, 0 = only our column lit)"},
          {"tdc.busy_time_s", K::Real, "s", 0, 1, true,
           "conversion + transfer time during which the TDC takes no new hit"},
          // Histogram and reconstruction (eq. 2.34 / 4.19).
          {"histogram.integration_time_s", K::Real, "s", 0, 100, true, "acquisition time of one pixel's histogram"},
          {"histogram.peak_window_bins", K::Integer, "", 1, 1e6, false,
           "peak window PW around the histogram maximum for the centroid, in TDC bins"},
          {"histogram.coates_correction", K::Boolean, "", 0, 0, false,
           "true: correct first-photon pile-up (Coates) before the centroid"},
          {"histogram.subtract_background", K::Boolean, "", 0, 0, false,
           "true: subtract the mean background per bin before the centroid"},
          {"histogram.readout_word_rate_Hz", K::Real, "Hz", 0, 10e9, true,
           "histogram words read out per second per output lane (one lane per TDC); sets the histogram_readout phase"},
          // Default evaluation grid (count rates, thesis 4.2.2).
          {"evaluation.signal_min_Hz", K::Real, "Hz", 0, 1e10, true,
           "lowest signal count rate (PDE-weighted, before dead-time losses)"},
          {"evaluation.signal_max_Hz", K::Real, "Hz", 0, 1e10, true, "highest signal count rate"},
          {"evaluation.signal_points", K::Integer, "", 1, 10000, false, "log-spaced signal points"},
          {"evaluation.background_min_Hz", K::Real, "Hz", 0, 1e10, true,
           "lowest background count rate (ambient light, without dark counts)"},
          {"evaluation.background_max_Hz", K::Real, "Hz", 0, 1e10, true, "highest background count rate"},
          {"evaluation.background_points", K::Integer, "", 1, 10000, false, "log-spaced background points"},
          {"evaluation.frames_averaged", K::Integer, "", 1, 100000, false, "histograms averaged per range value"},
          {"evaluation.distance_m", K::Real, "m", 0, 1e4, true, "target distance for single-point figures"},
          {"evaluation.distance_min_m", K::Real, "m", 0, 1e4, false, "nearest target distance of the evaluation"},
          {"evaluation.distance_max_m", K::Real, "m", 0, 1e4, true, "farthest target distance"},
          {"evaluation.distance_points", K::Integer, "", 1, 100000, false, "linearly spaced distance points"},
          {"evaluation.detection_sigma", K::Real, "", 0, 100, false,
           "k: signal counts in the peak window must exceed k sqrt(background counts in it)"},
          {"evaluation.min_signal_counts", K::Real, "", 0, 1e9, false,
           "minimum expected signal counts in the peak window"},
          {"evaluation.min_armed_fraction", K::Real, "", 0, 1, false,
           "pile-up saturated below this fraction of cycles still armed at the echo"},
          {"evaluation.reference_signal_Hz", K::Real, "Hz", 0, 1e10, true,
           "signal count rate of the published single-point figures"},
          {"evaluation.reference_background_Hz", K::Real, "Hz", 0, 1e10, false,
           "background count rate of the published single-point figures"},
          {"evaluation.sweep_signal_Hz", K::Real, "Hz", 0, 1e10, true,
           "fixed signal count rate of the accuracy-vs-background sweep"},
      }};
  // The non-idealities' keys (core/nonideal.h).
  static const ParamSchema schema =
      with_specs(base, {fixed_pattern_specs("Hz", 1e9, false, false),
                        blur_specs(false),
                        multipath_specs(),
                        dark_temperature_specs(),
                        {{"spad.temperature_K", ParamKind::Real, "K", 0, 500, true,
                          "sensor temperature: the dark count rate follows it (dark.*)"}}});
  return schema;
}

// The core part of the sensor interface (core/sensor_registry.h).
const SensorInfo& tof_spad_sensor_info() {
  static const SensorInfo info{
      "tof-spad",
      "direct time-of-flight, SPADs with column TDCs",
      "[11]",
      &tof_spad_schema,
      [](const ParamSet& p) { (void)tof_spad_from_params(p); },
      SceneRules{{"plane", "step", "depth_map"},
                 {"target.step_distance_m", "target.step_column", "beam.first_row", "beam.rows", "beam.first_column",
                  "beam.columns", "rates.signal_Hz", "rates.reference_distance_m", "rates.background_Hz",
                  "window.first_row", "window.rows", "window.first_column", "window.columns"},
                 {},
                 false,
                 false},
      &tof_spad_radiometry};
  return info;
}

}  // namespace rangesim
