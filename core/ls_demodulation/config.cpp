#include "core/ls_demodulation/config.h"

#include <cmath>

#include <fmt/format.h>

#include "core/user_error.h"

namespace rangesim {

LsDemodulationConfig ls_demodulation_from_params(const ParamSet& p) {
  LsDemodulationConfig c;
  auto integer = [&](const char* key) { return static_cast<int>(p.integer(key)); };
  c.pixel.columns = integer("pixel.columns");
  c.pixel.rows = integer("pixel.rows");
  c.pixel.pitch_m = p.real("pixel.pitch_m");
  c.pixel.fill_factor = p.real("pixel.fill_factor");
  c.pixel.responsivity_A_per_W = p.real("pixel.responsivity_A_per_W");
  c.pixel.integration_time_s = p.real("pixel.integration_time_s");

  c.modulation.frequency_Hz = p.real("modulation.frequency_Hz");
  c.modulation.source_duty_cycle = p.real("modulation.source_duty_cycle");
  c.modulation.reference_phase_rad = p.real("modulation.reference_phase_rad");

  c.suppression.mirror_gain = p.real("suppression.mirror_gain");
  c.suppression.mirror_mismatch = p.real("suppression.mirror_mismatch");
  c.suppression.lpf_time_constant_s = p.real("suppression.lpf_time_constant_s");

  c.log_converter.gain = p.real("log_converter.gain");
  c.log_converter.slope_V = p.real("log_converter.slope_V");
  c.log_converter.offset_current_A = p.real("log_converter.offset_current_A");
  c.log_converter.leakage_current_A = p.real("log_converter.leakage_current_A");

  c.correlator.capacitance_plus_F = p.real("correlator.capacitance_plus_F");
  c.correlator.capacitance_minus_F = p.real("correlator.capacitance_minus_F");
  c.correlator.transconductance_S = p.real("correlator.transconductance_S");
  c.correlator.reference_duty_cycle = p.real("correlator.reference_duty_cycle");
  c.correlator.cycles = integer("correlator.cycles");
  c.correlator.saturation_voltage_V = p.real("correlator.saturation_voltage_V");

  c.comparator.threshold_V = p.real("comparator.threshold_V");
  c.comparator.adc_bits = integer("comparator.adc_bits");
  c.comparator.false_activation_max = p.real("comparator.false_activation_max");

  c.noise.temperature_K = p.real("noise.temperature_K");
  c.dark = read_dark_temperature(p);
  c.noise.dark_current_A = p.real("noise.dark_current_A") * c.dark.scale(c.noise.temperature_K);
  c.fixed_pattern = read_fixed_pattern(p, "A", false, true);
  c.noise.read_noise_V = p.real("noise.read_noise_V");
  c.noise.fixed_pattern_rms_V = p.real("noise.fixed_pattern_rms_V");

  c.spot.fwhm_px = p.real("spot.fwhm_px");
  c.spot.sigma_per_fwhm = p.real("spot.sigma_per_fwhm");

  c.readout.clock_Hz = p.real("readout.clock_Hz");
  c.readout.row_cycles = integer("readout.row_cycles");
  c.readout.address_bits = integer("readout.address_bits");

  c.optics.focal_length_m = p.real("optics.focal_length_m");
  c.optics.f_number = p.real("optics.f_number");
  c.blur = read_blur(p, 0.0, c.optics.f_number, c.pixel.pitch_m);
  c.optics.baseline_m = p.real("optics.baseline_m");
  c.optics.distance_m = p.real("optics.distance_m");
  c.distance_min_m = p.real("optics.distance_min_m");
  c.distance_max_m = p.real("optics.distance_max_m");

  c.grid.signal_min_A = p.real("evaluation.signal_min_A");
  c.grid.signal_max_A = p.real("evaluation.signal_max_A");
  c.grid.signal_points = integer("evaluation.signal_points");
  c.grid.background_min_A = p.real("evaluation.background_min_A");
  c.grid.background_max_A = p.real("evaluation.background_max_A");
  c.grid.background_points = integer("evaluation.background_points");
  c.grid.subpixel_points = integer("evaluation.subpixel_points");
  c.grid.frames_averaged = integer("evaluation.frames_averaged");
  c.grid.detections = integer("evaluation.detections");
  c.min_detecting_fraction = p.real("validity.min_detecting_fraction");
  c.edge_margin_px = p.real("validity.edge_margin_px");
  c.grid.sweep_background_A = p.real("evaluation.sweep_background_A");

  // Cross-key checks.
  const double window_s = c.correlator.cycles / c.modulation.frequency_Hz;
  if (std::fabs(window_s - c.pixel.integration_time_s) > 1e-6 * c.pixel.integration_time_s)
    throw UserError(
        fmt::format("{}: correlator.cycles / modulation.frequency_Hz = {:g} s differs from "
                    "pixel.integration_time_s = {:g} s; allowed: equal within 1e-6 (the window is whole periods)",
                    p.origin(), window_s, c.pixel.integration_time_s),
        "correlator.cycles");
  if (c.comparator.adc_bits != 1)
    throw UserError(fmt::format("{}: comparator.adc_bits = {} is not modelled; allowed: 1 (Table 3.2)", p.origin(),
                                c.comparator.adc_bits),
                    "comparator.adc_bits");
  if ((1LL << c.readout.address_bits) < c.pixel.columns)
    throw UserError(fmt::format("{}: readout.address_bits = {} cannot address pixel.columns = {}; allowed: "
                                "address_bits >= ceil(log2(columns))",
                                p.origin(), c.readout.address_bits, c.pixel.columns),
                    "readout.address_bits");
  if (c.grid.signal_min_A > c.grid.signal_max_A)
    throw UserError(
        fmt::format("{}: evaluation.signal_min_A = {:g} > evaluation.signal_max_A = {:g}; allowed: min <= max",
                    p.origin(), c.grid.signal_min_A, c.grid.signal_max_A),
        "evaluation.signal_min_A");
  if (c.grid.background_min_A > c.grid.background_max_A)
    throw UserError(fmt::format("{}: evaluation.background_min_A = {:g} > evaluation.background_max_A = {:g}; allowed: "
                                "min <= max",
                                p.origin(), c.grid.background_min_A, c.grid.background_max_A),
                    "evaluation.background_min_A");
  if (c.distance_min_m > c.distance_max_m)
    throw UserError(fmt::format("{}: optics.distance_min_m = {:g} > optics.distance_max_m = {:g}; allowed: min <= max",
                                p.origin(), c.distance_min_m, c.distance_max_m),
                    "optics.distance_min_m");
  return c;
}

int readout_search_cycles(const DemodReadoutConfig& r) { return r.row_cycles - 1 - 2 * r.address_bits; }

}  // namespace rangesim
