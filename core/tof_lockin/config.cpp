#include "core/tof_lockin/config.h"

#include <cmath>

#include <fmt/format.h>

#include "core/user_error.h"

namespace rangesim {

namespace {

void require_ordered(const ParamSet& p, const char* lo_key, const char* hi_key) {
  if (p.real(lo_key) > p.real(hi_key))
    throw UserError(fmt::format("{}: {} = {:g} > {} = {:g}; allowed: min <= max", p.origin(), lo_key, p.real(lo_key),
                                hi_key, p.real(hi_key)),
                    lo_key);
}

}  // namespace

TofLockinConfig tof_lockin_from_params(const ParamSet& p) {
  TofLockinConfig c;
  c.pixel.columns = static_cast<int>(p.integer("pixel.columns"));
  c.pixel.rows = static_cast<int>(p.integer("pixel.rows"));
  c.pixel.pitch_m = p.real("pixel.pitch_m");
  c.pixel.fill_factor = p.real("pixel.fill_factor");
  c.pixel.responsivity_A_per_W = p.real("pixel.responsivity_A_per_W");
  c.optics.focal_length_m = p.real("optics.focal_length_m");
  c.optics.f_number = p.real("optics.f_number");
  c.pixel.fd1_capacitance_F = p.real("pixel.fd1_capacitance_F");
  c.pixel.fd2_capacitance_F = p.real("pixel.fd2_capacitance_F");
  c.pixel.source_follower_gain = p.real("pixel.source_follower_gain");
  c.pixel.saturation_voltage_V = p.real("pixel.saturation_voltage_V");
  c.pixel.offset_voltage_V = p.real("pixel.offset_voltage_V");
  c.pixel.charge_separation = p.real("pixel.charge_separation");
  c.pixel.drain_efficiency = p.real("pixel.drain_efficiency");

  c.source.wavelength_m = p.real("source.wavelength_m");
  c.source.pulse_width_s = p.real("source.pulse_width_s");
  c.source.duty_cycle = p.real("source.duty_cycle");
  c.source.rise_time_s = p.real("source.rise_time_s");

  c.gates.clock_Hz = p.real("gates.clock_Hz");
  c.gates.accumulations_per_frame = p.integer("gates.accumulations_per_frame");

  c.readout.adc_bits = static_cast<int>(p.integer("readout.adc_bits"));
  c.readout.adc_full_scale_V = p.real("readout.adc_full_scale_V");
  c.readout.detection_threshold_V = p.real("readout.detection_threshold_V");
  c.readout.min_snr = p.real("readout.min_snr");
  c.readout.max_range_noise_fraction = p.real("readout.max_range_noise_fraction");
  c.readout.cds_enabled = p.boolean("readout.cds_enabled");
  c.readout.ambient_subtraction = p.boolean("readout.ambient_subtraction");
  c.readout.offset_calibration_V = p.real("readout.offset_calibration_V");
  c.readout.clock_Hz = p.real("readout.clock_Hz");
  c.readout.adc_conversion_cycles = p.integer("readout.adc_conversion_cycles");
  c.readout.output_cycles_per_row = p.integer("readout.output_cycles_per_row");

  c.noise.temperature_K = p.real("noise.temperature_K");
  c.nonideal.dark = read_dark_temperature(p);
  c.noise.dark_current_A = p.real("noise.dark_current_A") * c.nonideal.dark.scale(c.noise.temperature_K);
  c.nonideal.fixed_pattern = read_fixed_pattern(p, "A", true, false);
  c.nonideal.blur = read_blur(p, c.source.wavelength_m, c.optics.f_number, c.pixel.pitch_m);
  c.nonideal.multipath = read_multipath(p);
  c.nonideal.offset_shot_noise = p.boolean("offset_charge.shot_noise");
  c.noise.read_noise_V = p.real("noise.read_noise_V");
  c.noise.fixed_pattern_rms_V = p.real("noise.fixed_pattern_rms_V");

  c.simulation.merged_draws = p.boolean("simulation.merged_draws");
  c.simulation.direct_trials = p.boolean("simulation.direct_trials");
  c.simulation.code_tables = p.boolean("simulation.code_tables");

  c.eval.signal_min_A = p.real("evaluation.signal_min_A");
  c.eval.signal_max_A = p.real("evaluation.signal_max_A");
  c.eval.signal_points = static_cast<int>(p.integer("evaluation.signal_points"));
  c.eval.background_min_A = p.real("evaluation.background_min_A");
  c.eval.background_max_A = p.real("evaluation.background_max_A");
  c.eval.background_points = static_cast<int>(p.integer("evaluation.background_points"));
  c.eval.frames_averaged = p.integer("evaluation.frames_averaged");
  c.eval.distance_m = p.real("evaluation.distance_m");
  c.eval.distance_min_m = p.real("evaluation.distance_min_m");
  c.eval.distance_max_m = p.real("evaluation.distance_max_m");
  c.eval.distance_points = static_cast<int>(p.integer("evaluation.distance_points"));

  // Cross-key checks.
  require_ordered(p, "evaluation.signal_min_A", "evaluation.signal_max_A");
  require_ordered(p, "evaluation.background_min_A", "evaluation.background_max_A");
  require_ordered(p, "evaluation.distance_min_m", "evaluation.distance_max_m");
  // The trapezoid's ramps (rise_time / 0.8 each) must fit inside the pulse width.
  if (c.source.rise_time_s / 0.8 > c.source.pulse_width_s)
    throw UserError(fmt::format("{}: source.rise_time_s = {:g} is longer than 0.8 x source.pulse_width_s = {:g}; "
                                "allowed: rise_time_s <= 0.8 pulse_width_s",
                                p.origin(), c.source.rise_time_s, 0.8 * c.source.pulse_width_s),
                    "source.rise_time_s");
  // Gate edges are generated on the gate clock: T0 must be a whole number of its cycles.
  const double cycles = c.source.pulse_width_s * c.gates.clock_Hz;
  if (std::fabs(cycles - std::round(cycles)) > 1e-6 || std::round(cycles) < 1)
    throw UserError(fmt::format("{}: source.pulse_width_s = {:g} is {:g} cycles of gates.clock_Hz = {:g}; allowed: a "
                                "whole number >= 1 of gate clock cycles",
                                p.origin(), c.source.pulse_width_s, cycles, c.gates.clock_Hz),
                    "source.pulse_width_s");
  return c;
}

}  // namespace rangesim
