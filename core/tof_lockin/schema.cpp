// Schema of presets/tof-lockin.toml (thesis [12], section 2.3 / 4.1, Table 4.1).
// Data flow: pulsed LED (T0, 10% duty) -> photogate PG -> TX1/TX2 to FD1/FD2 in PHASE1/PHASE2,
// TXD drains in PHASE3 (eq. 2.17-2.19), repeated N times per frame -> source followers ->
// column ADC (eq. 4.9) -> optional ambient-frame subtraction -> L = c T0 (V2 - V_off) /
// (2 (V1 + V2 - 2 V_off)) (eq. 2.25) -> frame averaging. Config struct: core/tof_lockin/config.h.
#include "core/tof_lockin/config.h"
#include "core/nonideal.h"
#include "core/schemas.h"
#include "core/sensor_registry.h"

namespace rangesim {

const ParamSchema& tof_lockin_schema() {
  using K = ParamKind;
  static const ParamSchema base{
      "tof-lockin",
      {
          // Pixel: photogate, two floating diffusions, source followers (eq. 2.17-2.25).
          {"pixel.columns", K::Integer, "", 1, 4096, false, "pixels per row"},
          {"pixel.rows", K::Integer, "", 1, 4096, false, "rows"},
          {"pixel.pitch_m", K::Real, "m", 0, 1e-3, true, "pixel pitch"},
          {"pixel.fill_factor", K::Real, "", 0, 1, true,
           "photogate share of the pixel area (radiometry of physical scenes and axes)"},
          {"pixel.responsivity_A_per_W", K::Real, "A_per_W", 0, 2, true,
           "photogate responsivity at the source wavelength (radiometry of physical scenes and axes)"},
          {"optics.focal_length_m", K::Real, "m", 0, 10, true, "lens focal length (radiometry: field of view)"},
          {"optics.f_number", K::Real, "", 0.5, 64, false, "lens F# (radiometry of physical scenes and axes)"},
          {"pixel.fd1_capacitance_F", K::Real, "F", 0, 1e-9, true,
           "capacitance of floating diffusion FD1 (collects N1 through TX1)"},
          {"pixel.fd2_capacitance_F", K::Real, "F", 0, 1e-9, true,
           "capacitance of floating diffusion FD2 (collects N2 through TX2)"},
          {"pixel.source_follower_gain", K::Real, "", 0, 10, true,
           "source-follower gain A_sf; conversion gain = A_sf q / C_FD"},
          {"pixel.saturation_voltage_V", K::Real, "V", 0, 10, true,
           "FD swing at saturation (signal + background + offset)"},
          {"pixel.offset_voltage_V", K::Real, "V", 0, 10, false,
           "offset V_offset on each FD from deep-generated electrons (eq. 2.25)"},
          {"pixel.charge_separation", K::Real, "", 0.5, 1, false,
           "fraction of electrons generated while TXk is open that reach FDk (1 = ideal)"},
          {"pixel.drain_efficiency", K::Real, "", 0, 1, false,
           "fraction of PHASE3 electrons removed by TXD; the rest splits evenly over FD1/FD2 (1 = ideal)"},
          // Light source (LED array).
          {"source.wavelength_m", K::Real, "m", 0, 1e-5, true, "LED wavelength"},
          {"source.pulse_width_s", K::Real, "s", 0, 1e-3, true, "light pulse width T0 (= TX1 and TX2 open time)"},
          {"source.duty_cycle", K::Real, "", 0, 0.5, true, "light duty cycle; repetition period = T0 / duty"},
          {"source.rise_time_s", K::Real, "s", 0, 1e-3, false,
           "10-90% rise and fall time of the light pulse (0 = rectangular)"},
          // Lock-in gate timing (PHASE1 / PHASE2 / PHASE3).
          {"gates.clock_Hz", K::Real, "Hz", 0, 100e9, true,
           "timing clock of the gate pulse generator (gate edges on its grid)"},
          {"gates.accumulations_per_frame", K::Integer, "", 1, 1e9, false,
           "charge-transfer cycles N accumulated on the FDs per frame"},
          // Readout: column ADC and frame schedule.
          {"readout.adc_bits", K::Integer, "", 1, 24, false, "column ADC resolution"},
          {"readout.adc_full_scale_V", K::Real, "V", 0, 10, true,
           "ADC input range; LSB Delta V_ADC = full scale / 2^bits (eq. 4.9)"},
          {"readout.detection_threshold_V", K::Real, "V", 0, 10, true,
           "smallest V1 + V2 - 2 V_offset accepted as a range value (V_sig_min of eq. 4.11)"},
          {"readout.min_snr", K::Real, "", 0, 1e6, false,
           "smallest SNR of V1 + V2 - 2 V_offset (mean over rms) for which a range is derived; below it the ratio's "
           "moments diverge"},
          {"readout.max_range_noise_fraction", K::Real, "", 0, 1e6, true,
           "largest rms noise of one range value (delta method, from the tap values) as a fraction of the "
           "unambiguous range c T0 / 2 for which a range counts: golden's detectability, the range maps' validity"},
          {"readout.cds_enabled", K::Boolean, "", 0, 0, false,
           "true: FD reset level sampled and subtracted, cancelling kTC noise"},
          {"readout.ambient_subtraction", K::Boolean, "", 0, 0, false,
           "true: a frame with the LED off is read and subtracted from each tap (cancels background, dark and "
           "V_offset; doubles reset/read noise and readouts)"},
          {"readout.offset_calibration_V", K::Real, "V", 0, 10, false,
           "V_offset subtracted from each tap in eq. 2.25 after the (optional) ambient subtraction; a mismatch with "
           "the true offset biases L"},
          {"readout.clock_Hz", K::Real, "Hz", 0, 10e9, true, "readout clock"},
          {"readout.adc_conversion_cycles", K::Integer, "", 1, 1e9, false,
           "clock cycles of one column-parallel conversion (both FDs of a row)"},
          {"readout.output_cycles_per_row", K::Integer, "", 1, 1e9, false,
           "clock cycles to shift out one row of converted values"},
          // Noise.
          {"noise.temperature_K", K::Real, "K", 0, 500, true, "temperature for kTC reset noise"},
          {"noise.dark_current_A", K::Real, "A", 0, 1e-9, false,
           "dark current into each FD, per pixel, at dark.reference_temperature_K (scaled to noise.temperature_K)"},
          {"noise.read_noise_V", K::Real, "V", 0, 1, false, "source-follower and ADC input noise, rms, per sample"},
          {"noise.fixed_pattern_rms_V", K::Real, "V", 0, 1, false, "pixel-to-pixel offset, rms (0 = off)"},
          // Default evaluation grid (thesis Fig. 4.4-4.6).
          {"evaluation.signal_min_A", K::Real, "A", 0, 1, true,
           "lowest signal photocurrent I_ph (during the light pulse) of the grid"},
          {"evaluation.signal_max_A", K::Real, "A", 0, 1, true, "highest signal photocurrent of the grid"},
          {"evaluation.signal_points", K::Integer, "", 1, 10000, false, "log-spaced signal points"},
          {"evaluation.background_min_A", K::Real, "A", 0, 1, true, "lowest background photocurrent I_dc of the grid"},
          {"evaluation.background_max_A", K::Real, "A", 0, 1, true, "highest background photocurrent of the grid"},
          {"evaluation.background_points", K::Integer, "", 1, 10000, false, "log-spaced background points"},
          {"evaluation.frames_averaged", K::Integer, "", 1, 100000, false,
           "frames N averaged per range value (the noise falls as 1/sqrt(N), the fixed pattern does not)"},
          {"evaluation.distance_m", K::Real, "m", 0, 1e4, true, "target distance for single-point figures"},
          {"evaluation.distance_min_m", K::Real, "m", 0, 1e4, false, "nearest target distance of the evaluation"},
          {"evaluation.distance_max_m", K::Real, "m", 0, 1e4, true, "farthest target distance (at most c T0 / 2)"},
          {"evaluation.distance_points", K::Integer, "", 1, 100000, false, "linearly spaced distance points"},
      }};
  // The non-idealities' keys (core/nonideal.h).
  static const ParamSchema schema = with_specs(
      base,
      {fixed_pattern_specs("A", 1e-9, true, false),
       blur_specs(false),
       dark_temperature_specs(),
       multipath_specs(),
       {{"offset_charge.shot_noise", ParamKind::Boolean, "", 0, 0, false,
         "true: the offset charge on each FD (pixel.offset_voltage_V x C, deep electrons) is Poisson, drawn every "
         "frame"},
        {"simulation.merged_draws", ParamKind::Boolean, "", 0, 0, false,
         "true: an aggregated frame draws one Poisson count per tap (frame and offset charge) and, where V_sat "
         "cannot be reached, one normal (kTC and read noise); false: every noise term apart (same law)"},
        {"simulation.direct_trials", ParamKind::Boolean, "", 0, 0, false,
         "true: evaluate --trials draws each trial's frames without stepping the frame schedule (the kernel's "
         "draws, bit for bit); false: every trial runs the sensor kernel"},
        {"simulation.code_tables", ParamKind::Boolean, "", 0, 0, false,
         "true: from a point's 65536th trial on, evaluate --trials (with direct_trials) draws each tap's ADC code "
         "from its exact law where V_sat cannot be reached (same law); false: the count and the noise apart"}}});
  return schema;
}

// The core part of the sensor interface (core/sensor_registry.h).
const SensorInfo& tof_lockin_sensor_info() {
  static const SensorInfo info{
      "tof-lockin",
      "pulsed lock-in time-of-flight, two-tap photogate",
      "[12]",
      &tof_lockin_schema,
      [](const ParamSet& p) { (void)tof_lockin_from_params(p); },
      SceneRules{{"plane", "step", "depth_map"},
                 {"target.near_distance_m", "target.step_column_fraction", "light.signal_photocurrent_A",
                  "light.reference_distance_m", "light.background_photocurrent_A", "window.rows", "window.columns"},
                 {"scene.name", "light.signal_photocurrent_A"},
                 true,
                 false},
      &tof_lockin_radiometry};
  return info;
}

}  // namespace rangesim
