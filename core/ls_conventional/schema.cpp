// Schema of presets/ls-conventional.toml (thesis [31], Table 3.1).
#include "core/ls_conventional/config.h"
#include "core/nonideal.h"
#include "core/schemas.h"
#include "core/sensor_registry.h"

namespace rangesim {

const ParamSchema& ls_conventional_schema() {
  using K = ParamKind;
  static const ParamSchema base{
      "ls-conventional",
      {
          // Pixel front-end (thesis eq. 3.1-3.4).
          {"pixel.integration_time_s", K::Real, "s", 0, 1, true, "photo-integration time t (eq. 3.1)"},
          {"pixel.pd_capacitance_F", K::Real, "F", 0, 1e-9, true, "photodiode well capacity C_pd (eq. 3.1)"},
          {"pixel.source_follower_gain", K::Real, "", 0, 10, true, "source-follower gain A_sf (eq. 3.4)"},
          {"pixel.saturation_voltage_V", K::Real, "V", 0, 10, true, "pixel swing at saturation V_sat (eq. 3.3)"},
          {"pixel.dark_current_A", K::Real, "A", 0, 1e-9, false,
           "photodiode dark current at dark.reference_temperature_K (scaled to pixel.temperature_K)"},
          {"pixel.temperature_K", K::Real, "K", 0, 500, true,
           "sensor temperature: kTC reset noise and the dark current's temperature law"},
          {"pixel.read_noise_V", K::Real, "V", 0, 1, false,
           "input-referred source-follower/comparator noise, rms, per frame"},
          {"pixel.columns", K::Integer, "", 1, 4096, false, "pixels per row (search direction)"},
          {"pixel.rows", K::Integer, "", 1, 4096, false, "rows (searched in parallel)"},
          {"pixel.pitch_m", K::Real, "m", 0, 1e-3, true, "pixel pitch"},
          {"pixel.fill_factor", K::Real, "", 0, 1, true,
           "photosensitive area / pixel area (scene radiometry, rangesim simulate)"},
          {"pixel.responsivity_A_per_W", K::Real, "A_per_W", 0, 2, true,
           "photodiode responsivity in the beam's band (scene radiometry)"},
          // Beam spot on the focal plane (eq. 3.6).
          {"spot.fwhm_px", K::Real, "px", 0, 100, true, "FWHM of the Gaussian sheet-beam profile across a row"},
          {"spot.sigma_per_fwhm", K::Real, "", 0, 1, true, "sigma / FWHM (exact Gaussian 0.4247; thesis writes 0.45)"},
          // Comparator / column ADC (eq. 3.5, 3.7, 3.11).
          {"comparator.threshold_mode", K::Text, "", 0, 0, false, "threshold reference", {"tracking", "fixed"}},
          {"comparator.threshold_above_background_V", K::Real, "V", 0, 10, true,
           "tracking mode: V_cmp - V_bg = Delta V_ADC (eq. 3.11)"},
          {"comparator.fixed_threshold_V", K::Real, "V", 0, 10, true, "fixed mode: absolute V_cmp"},
          {"comparator.adc_bits", K::Integer, "", 1, 16, false, "bits per sampling (1 = comparator)"},
          {"comparator.false_activation_max", K::Real, "", 0, 1, true,
           "largest tolerated probability that background alone activates a pixel of the row"},
          // Multi-sampling during integration.
          {"multisampling.samplings", K::Integer, "", 1, 64, false, "samplings per integration"},
          // Frame timing from the clock schedule.
          {"timing.clock_Hz", K::Real, "Hz", 0, 10e9, true, "readout clock"},
          {"timing.reset_cycles", K::Integer, "", 0, 1e6, false, "pixel reset at frame start"},
          {"timing.latch_cycles", K::Integer, "", 1, 1e6, false, "comparator latch per sampling"},
          {"timing.search_cycles", K::Integer, "", 1, 1e6, false, "chained search settle per sampling"},
          {"timing.address_bits", K::Integer, "", 1, 32, false, "bits of the bit-streamed column address"},
          {"timing.addresses_per_sampling", K::Integer, "", 1, 64, false,
           "addresses streamed per sampling (left and right edge)"},
          {"timing.output_cycles", K::Integer, "", 0, 1e6, false,
           "centre output from the row processors per frame access"},
          {"timing.beam_positions", K::Integer, "", 1, 100000, false,
           "frame accesses per range map (sheet-beam positions)"},
          // Triangulation geometry (eq. 1.1-1.8).
          {"optics.focal_length_m", K::Real, "m", 0, 10, true, "lens focal length f"},
          {"optics.baseline_m", K::Real, "m", 0, 100, true, "baseline d between beam projector and lens"},
          {"optics.distance_m", K::Real, "m", 0, 1e4, true, "target distance l for the range-accuracy figures"},
          {"optics.f_number", K::Real, "", 0.5, 64, false,
           "lens f-number F# (scene radiometry: lens area, camera equation)"},
          // Default evaluation grid (thesis Fig. 3.3-3.4).
          {"evaluation.signal_min_V", K::Real, "V", 0, 100, true, "lowest signal voltage V_sig of the grid"},
          {"evaluation.signal_max_V", K::Real, "V", 0, 100, true, "highest signal voltage of the grid"},
          {"evaluation.signal_points", K::Integer, "", 1, 10000, false, "log-spaced signal points"},
          {"evaluation.background_min_V", K::Real, "V", 0, 100, true, "lowest background voltage V_bg of the grid"},
          {"evaluation.background_max_V", K::Real, "V", 0, 100, true, "highest background voltage of the grid"},
          {"evaluation.background_points", K::Integer, "", 1, 10000, false, "log-spaced background points"},
          {"evaluation.subpixel_points", K::Integer, "", 1, 4096, false,
           "spot positions across one pixel of the fixed midpoint rule used when subpixel_tolerance = 0"},
          {"evaluation.subpixel_tolerance", K::Real, "", 0, 0.5, false,
           "estimated relative error allowed in the accuracy, P(detect) and P(outlier) averaged over spot positions "
           "(adaptive Gauss-Kronrod between the noise-free breakpoints, at most 4096 positions; 0: the fixed rule of "
           "subpixel_points)"},
          // Range-map validity (rangesim simulate).
          {"validity.min_detecting_fraction", K::Real, "", 0, 1, false,
           "a row's range counts when at least this fraction of the samplings found the spot (0: any one, the "
           "centre processor's own rule)"},
          {"validity.edge_margin_px", K::Real, "px", 0, 1e4, false,
           "a row's centre counts only this far inside the array's first and last column: nearer, the spot may "
           "be clipped by the edge and its centre pulled inward"},
          // Clock-level model (rangesim simulate, evaluate --trials).
          {"simulation.exact_activation_sampling", K::Boolean, "", 0, 0, false,
           "draw each noisy pixel's first firing sampling from its exact distribution and skip pixels whose "
           "outcome is certain to 2^-56 (false: every noise term drawn and compared at every sampling)"},
          {"simulation.certain_intervals", K::Boolean, "", 0, 0, false,
           "with exact_activation_sampling and the sparse window: find a row's certain pixels as intervals "
           "around the spot centre and look only at the pixels between them one by one (false: every window "
           "pixel; the same bits either way)"},
          {"simulation.inversion_draw", K::Boolean, "", 0, 0, false,
           "with exact_activation_sampling: draw an uncertain pixel's first firing sampling with one uniform by "
           "inversion of its exact distribution function (false: a normal pair and a Gamma variate)"},
      }};
  // The non-idealities' keys (core/nonideal.h).
  static const ParamSchema schema =
      with_specs(base, {fixed_pattern_specs("A", 1e-9, false, true), blur_specs(true), dark_temperature_specs()});
  return schema;
}

// The core part of the sensor interface (core/sensor_registry.h).
const SensorInfo& ls_conventional_sensor_info() {
  static const SensorInfo info{
      "ls-conventional",
      "light-section, row-parallel search, multi-sampling",
      "[31]",
      &ls_conventional_schema,
      [](const ParamSet& p) { (void)ls_conventional_from_params(p); },
      SceneRules{
          {"plane", "tilted", "step", "depth_map"},
          {"target.reflectance", "target.tilt_x_rad", "target.tilt_y_rad", "target.near_distance_m", "target.step_y_m",
           "beam.power_W", "beam.reference_distance_m", "beam.column_offset_px", "background.irradiance_W_per_m2",
           "camera.f_number", "camera.fill_factor", "camera.responsivity_A_per_W"},
          {"scene.name", "target.shape", "target.reflectance", "beam.power_W", "beam.reference_distance_m",
           "background.irradiance_W_per_m2"},
          true,
          true},
      &ls_conventional_radiometry};
  return info;
}

}  // namespace rangesim
