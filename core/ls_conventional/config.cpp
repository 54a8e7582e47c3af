#include "core/ls_conventional/config.h"

#include <fmt/format.h>

#include "core/user_error.h"

namespace rangesim {

long long sampling_cycles(const FrameTimingConfig& timing) {
  return static_cast<long long>(timing.latch_cycles) + timing.search_cycles +
         static_cast<long long>(timing.addresses_per_sampling) * timing.address_bits;
}

long long frame_cycles(const FrameTimingConfig& timing, int samplings) {
  return timing.reset_cycles + samplings * sampling_cycles(timing) + timing.output_cycles;
}

LsConventionalConfig ls_conventional_from_params(const ParamSet& p) {
  LsConventionalConfig c;
  c.pixel.integration_time_s = p.real("pixel.integration_time_s");
  c.pixel.pd_capacitance_F = p.real("pixel.pd_capacitance_F");
  c.pixel.source_follower_gain = p.real("pixel.source_follower_gain");
  c.pixel.saturation_voltage_V = p.real("pixel.saturation_voltage_V");
  c.pixel.temperature_K = p.real("pixel.temperature_K");
  c.dark = read_dark_temperature(p);
  // The preset gives the dark current at the reference temperature; the models take it at the
  // sensor's (core/nonideal.h).
  c.pixel.dark_current_A = p.real("pixel.dark_current_A") * c.dark.scale(c.pixel.temperature_K);
  c.pixel.read_noise_V = p.real("pixel.read_noise_V");
  c.pixel.columns = static_cast<int>(p.integer("pixel.columns"));
  c.pixel.rows = static_cast<int>(p.integer("pixel.rows"));
  c.pixel.pitch_m = p.real("pixel.pitch_m");
  c.pixel.fill_factor = p.real("pixel.fill_factor");
  c.pixel.responsivity_A_per_W = p.real("pixel.responsivity_A_per_W");

  c.spot.fwhm_px = p.real("spot.fwhm_px");
  c.spot.sigma_per_fwhm = p.real("spot.sigma_per_fwhm");

  c.comparator.threshold_mode =
      p.text("comparator.threshold_mode") == "fixed" ? ThresholdMode::Fixed : ThresholdMode::Tracking;
  c.comparator.threshold_above_background_V = p.real("comparator.threshold_above_background_V");
  c.comparator.fixed_threshold_V = p.real("comparator.fixed_threshold_V");
  c.comparator.adc_bits = static_cast<int>(p.integer("comparator.adc_bits"));
  c.comparator.false_activation_max = p.real("comparator.false_activation_max");

  c.multisampling.samplings = static_cast<int>(p.integer("multisampling.samplings"));
  c.validity.min_detecting_fraction = p.real("validity.min_detecting_fraction");
  c.validity.edge_margin_px = p.real("validity.edge_margin_px");
  c.simulation.exact_activation_sampling = p.boolean("simulation.exact_activation_sampling");
  c.simulation.certain_intervals = p.boolean("simulation.certain_intervals");
  c.simulation.inversion_draw = p.boolean("simulation.inversion_draw");

  c.timing.clock_Hz = p.real("timing.clock_Hz");
  c.timing.reset_cycles = static_cast<int>(p.integer("timing.reset_cycles"));
  c.timing.latch_cycles = static_cast<int>(p.integer("timing.latch_cycles"));
  c.timing.search_cycles = static_cast<int>(p.integer("timing.search_cycles"));
  c.timing.address_bits = static_cast<int>(p.integer("timing.address_bits"));
  c.timing.addresses_per_sampling = static_cast<int>(p.integer("timing.addresses_per_sampling"));
  c.timing.output_cycles = static_cast<int>(p.integer("timing.output_cycles"));
  c.timing.beam_positions = static_cast<int>(p.integer("timing.beam_positions"));

  c.search.columns = c.pixel.columns;
  c.search.address_bits = c.timing.address_bits;
  c.search.addresses_per_sampling = c.timing.addresses_per_sampling;

  c.optics.focal_length_m = p.real("optics.focal_length_m");
  c.optics.baseline_m = p.real("optics.baseline_m");
  c.optics.distance_m = p.real("optics.distance_m");
  c.optics.f_number = p.real("optics.f_number");
  c.fixed_pattern = read_fixed_pattern(p, "A", false, true);
  c.blur = read_blur(p, 0.0, c.optics.f_number, c.pixel.pitch_m);

  c.grid.signal_min_V = p.real("evaluation.signal_min_V");
  c.grid.signal_max_V = p.real("evaluation.signal_max_V");
  c.grid.signal_points = static_cast<int>(p.integer("evaluation.signal_points"));
  c.grid.background_min_V = p.real("evaluation.background_min_V");
  c.grid.background_max_V = p.real("evaluation.background_max_V");
  c.grid.background_points = static_cast<int>(p.integer("evaluation.background_points"));
  c.grid.subpixel_points = static_cast<int>(p.integer("evaluation.subpixel_points"));
  c.grid.subpixel_tolerance = p.real("evaluation.subpixel_tolerance");

  // Cross-key checks: the column address must fit the row.
  if ((1LL << c.timing.address_bits) < c.pixel.columns)
    throw UserError(fmt::format("{}: timing.address_bits = {} cannot address pixel.columns = {}; allowed: "
                                "address_bits >= ceil(log2(columns))",
                                p.origin(), c.timing.address_bits, c.pixel.columns),
                    "timing.address_bits");
  if (c.grid.signal_min_V > c.grid.signal_max_V)
    throw UserError(
        fmt::format("{}: evaluation.signal_min_V = {:g} > evaluation.signal_max_V = {:g}; allowed: min <= max",
                    p.origin(), c.grid.signal_min_V, c.grid.signal_max_V),
        "evaluation.signal_min_V");
  if (c.grid.background_min_V > c.grid.background_max_V)
    throw UserError(
        fmt::format("{}: evaluation.background_min_V = {:g} > evaluation.background_max_V = {:g}; allowed: min <= max",
                    p.origin(), c.grid.background_min_V, c.grid.background_max_V),
        "evaluation.background_min_V");
  return c;
}

}  // namespace rangesim
