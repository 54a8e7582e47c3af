// Schema of presets/ls-demodulation.toml (thesis [27], section 2.2 / 3.2, Table 3.2).
// Data flow: photodiode -> current copier (alpha) with LPF background subtraction (eq. 2.8-2.10)
// -> log I-V converter (eq. 2.11) -> two correlating integrators switched by MPY+/MPY- at the
// correlation frequency (eq. 2.13) -> comparator V_out+ - V_out- >= V_cmp (eq. 2.12) -> position
// readout -> centroid (eq. 3.18-3.22) -> triangulation.
#include "core/ls_demodulation/config.h"
#include "core/nonideal.h"
#include "core/schemas.h"
#include "core/sensor_registry.h"

namespace rangesim {

const ParamSchema& ls_demodulation_schema() {
  using K = ParamKind;
  static const ParamSchema base{
      "ls-demodulation",
      {
          // Pixel array and photo-integration.
          {"pixel.columns", K::Integer, "", 1, 4096, false, "pixels per row (position-detection direction)"},
          {"pixel.rows", K::Integer, "", 1, 4096, false, "rows"},
          {"pixel.pitch_m", K::Real, "m", 0, 1e-3, true, "pixel pitch"},
          {"pixel.fill_factor", K::Real, "", 0, 1, true,
           "photodiode share of the pixel area (radiometry of physical scenes and axes)"},
          {"pixel.responsivity_A_per_W", K::Real, "A_per_W", 0, 2, true,
           "photodiode responsivity in the beam's band (radiometry of physical scenes and axes)"},
          {"pixel.integration_time_s", K::Real, "s", 0, 1, true,
           "correlation (integration) time T per output, eq. 2.13"},
          // Light source modulation and correlation reference.
          {"modulation.frequency_Hz", K::Real, "Hz", 0, 1e9, true,
           "correlation frequency f0 of the beam modulation and of MPY+/MPY-"},
          {"modulation.source_duty_cycle", K::Real, "", 0, 1, true, "fraction of each period the modulated beam is on"},
          {"modulation.reference_phase_rad", K::Real, "rad", -6.283185307179586, 6.283185307179586, false,
           "phase of MPY+ relative to the beam-on edge (0 = aligned)"},
          // Current copier and low-pass-filter background subtraction (eq. 2.8-2.10).
          {"suppression.mirror_gain", K::Real, "", 0, 1000, true, "current copier gain alpha (eq. 2.9-2.10)"},
          {"suppression.mirror_mismatch", K::Real, "", -0.5, 0.5, false,
           "relative mismatch alpha'/alpha - 1 of the two copier branches (eq. 2.10)"},
          {"suppression.lpf_time_constant_s", K::Real, "s", 0, 10, true,
           "time constant of the LPF that forms alpha I_avg (set by V_r)"},
          // Logarithmic I-V converter (eq. 2.11).
          {"log_converter.gain", K::Real, "", 0, 100, true, "gain factor beta of the log I-V converter (eq. 2.11)"},
          {"log_converter.slope_V", K::Real, "V", 0, 1, true,
           "log slope per e-fold of current (n kT/q); V_mod = beta slope ln(I_offset + I_mod)"},
          {"log_converter.offset_current_A", K::Real, "A", 0, 1e-3, true,
           "offset current I_offset of the log converter (eq. 2.11)"},
          {"log_converter.leakage_current_A", K::Real, "A", 0, 1e-6, true,
           "floor of I_offset + I_mod (junction leakage); swings below it are clipped"},
          // Correlating integrators switched by MPY+/MPY- (eq. 2.12-2.13).
          {"correlator.capacitance_plus_F", K::Real, "F", 0, 1e-9, true,
           "integration capacitor of the MPY+ branch (C1)"},
          {"correlator.capacitance_minus_F", K::Real, "F", 0, 1e-9, true,
           "integration capacitor of the MPY- branch (C2)"},
          {"correlator.transconductance_S", K::Real, "S", 0, 1, true,
           "transconductance that integrates V_mod onto the capacitors"},
          {"correlator.reference_duty_cycle", K::Real, "", 0, 1, true,
           "fraction of each period MPY+ is active (0.5 rejects even harmonics)"},
          {"correlator.cycles", K::Integer, "", 1, 1e9, false, "correlation periods N summed per output (eq. 2.13)"},
          {"correlator.saturation_voltage_V", K::Real, "V", 0, 10, true,
           "swing of each integrator output before it saturates"},
          // Comparator / 1-bit ADC (eq. 2.12, 3.19).
          {"comparator.threshold_V", K::Real, "V", 0, 10, true,
           "reference V_cmp: active when V_out+ - V_out- >= V_cmp (eq. 2.12)"},
          {"comparator.adc_bits", K::Integer, "", 1, 1, false,
           "bits per conversion (only the 1-bit comparator of Table 3.2 is modelled)"},
          {"comparator.false_activation_max", K::Real, "", 0, 1, true,
           "tolerated probability that background alone activates a pixel of the row"},
          // Noise.
          {"noise.temperature_K", K::Real, "K", 0, 500, true, "temperature for kTC and thermal noise"},
          {"noise.dark_current_A", K::Real, "A", 0, 1e-9, false,
           "photodiode dark current at dark.reference_temperature_K, scaled to noise.temperature_K (adds to I_dc, with "
           "its shot noise)"},
          {"noise.read_noise_V", K::Real, "V", 0, 1, false,
           "source-follower/comparator noise on V_out+ - V_out-, rms, per output"},
          {"noise.fixed_pattern_rms_V", K::Real, "V", 0, 1, false,
           "comparator offset, rms, drawn anew at every decision (a noise; fixed_pattern.comparator_offset_rms_V is "
           "the offset fixed per pixel; 0 = off)"},
          // Beam spot on the focal plane (eq. 3.18).
          {"spot.fwhm_px", K::Real, "px", 0, 100, true, "FWHM of the Gaussian sheet-beam profile across a row"},
          {"spot.sigma_per_fwhm", K::Real, "", 0, 1, true, "sigma / FWHM (exact Gaussian 0.4247; thesis writes 0.45)"},
          // Position readout.
          {"readout.clock_Hz", K::Real, "Hz", 0, 10e9, true, "readout clock"},
          {"readout.row_cycles", K::Integer, "", 1, 1e6, false,
           "clock cycles to read one row of comparator outputs and encode its position"},
          {"readout.address_bits", K::Integer, "", 1, 32, false, "bits of a column address"},
          // Triangulation geometry (eq. 1.1-1.8).
          {"optics.focal_length_m", K::Real, "m", 0, 10, true, "lens focal length f"},
          {"optics.f_number", K::Real, "", 0.5, 64, false, "lens F# (radiometry of physical scenes and axes)"},
          {"optics.baseline_m", K::Real, "m", 0, 100, true, "baseline d between beam projector and lens"},
          {"optics.distance_m", K::Real, "m", 0, 1e4, true, "target distance for single-point range-accuracy figures"},
          {"optics.distance_min_m", K::Real, "m", 0, 1e4, true, "nearest target distance of the evaluation"},
          {"optics.distance_max_m", K::Real, "m", 0, 1e4, true, "farthest target distance of the evaluation"},
          // Default evaluation grid (thesis Fig. 3.5-3.9).
          {"evaluation.signal_min_A", K::Real, "A", 0, 1, true,
           "lowest signal photocurrent (beam-on level at the spot centre) of the grid"},
          {"evaluation.signal_max_A", K::Real, "A", 0, 1, true, "highest signal photocurrent of the grid"},
          {"evaluation.signal_points", K::Integer, "", 1, 10000, false, "log-spaced signal points"},
          {"evaluation.background_min_A", K::Real, "A", 0, 1, true, "lowest background photocurrent I_dc of the grid"},
          {"evaluation.background_max_A", K::Real, "A", 0, 1, true, "highest background photocurrent of the grid"},
          {"evaluation.background_points", K::Integer, "", 1, 10000, false, "log-spaced background points"},
          {"evaluation.subpixel_points", K::Integer, "", 1, 4096, false,
           "spot positions across one pixel averaged for accuracy"},
          {"evaluation.frames_averaged", K::Integer, "", 1, 100000, false,
           "frames N_p averaged per range value (accuracy ~ 1/sqrt(N_p))"},
          {"evaluation.detections", K::Integer, "", 1, 100000, false,
           "correlation decisions per frame whose centres are averaged (thesis Fig. 3.9)"},
          {"evaluation.sweep_background_A", K::Real, "A", 0, 1, true,
           "background photocurrent of the one-dimensional accuracy sweeps"},
          // Range-map validity (rangesim simulate).
          {"validity.min_detecting_fraction", K::Real, "", 0, 1, false,
           "a row's range counts when at least this fraction of the frame's correlation decisions found the spot "
           "(0: any one)"},
          {"validity.edge_margin_px", K::Real, "px", 0, 1e4, false,
           "a row's centre counts only this far inside the array's first and last column: nearer, the spot may "
           "be clipped by the edge and its centre pulled inward"},
      }};
  // The non-idealities' keys (core/nonideal.h).
  static const ParamSchema schema =
      with_specs(base, {fixed_pattern_specs("A", 1e-6, false, true), blur_specs(true), dark_temperature_specs()});
  return schema;
}

// The core part of the sensor interface (core/sensor_registry.h).
const SensorInfo& ls_demodulation_sensor_info() {
  static const SensorInfo info{"ls-demodulation",
                               "light-section, demodulation, background suppression",
                               "[27]",
                               &ls_demodulation_schema,
                               [](const ParamSet& p) { (void)ls_demodulation_from_params(p); },
                               SceneRules{{"plane", "depth_map"},
                                          {"target.tilt_m_per_row", "beam.signal_A", "beam.first_column_px",
                                           "beam.columns_per_frame", "background.photocurrent_A"},
                                          {"scene.name", "beam.signal_A", "background.photocurrent_A"},
                                          false,
                                          false},
                               &ls_demodulation_radiometry};
  return info;
}

}  // namespace rangesim
