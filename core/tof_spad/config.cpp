#include "core/tof_spad/config.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "core/user_error.h"

namespace rangesim {

namespace {

void check_order(const ParamSet& p, const char* lo_key, double lo, const char* hi_key, double hi) {
  if (lo > hi)
    throw UserError(fmt::format("{}: {} = {:g} > {} = {:g}; allowed: min <= max", p.origin(), lo_key, lo, hi_key, hi),
                    lo_key);
}

}  // namespace

TofSpadConfig tof_spad_from_params(const ParamSet& p) {
  TofSpadConfig c;
  c.spad.pde = p.real("spad.pde");
  c.array.rows = static_cast<int>(p.integer("array.rows"));
  c.array.columns = static_cast<int>(p.integer("array.columns"));
  c.array.pitch_m = p.real("array.pitch_m");
  c.array.focal_length_m = p.real("optics.focal_length_m");
  c.array.f_number = p.real("optics.f_number");
  c.spad.fill_factor = p.real("spad.fill_factor");
  c.temperature_K = p.real("spad.temperature_K");
  c.dark = read_dark_temperature(p);
  c.spad.dark_count_rate_Hz = p.real("spad.dark_count_rate_Hz") * c.dark.scale(c.temperature_K);
  c.fixed_pattern = read_fixed_pattern(p, "Hz", false, false);
  c.blur = read_blur(p, p.real("laser.wavelength_m"), p.real("optics.f_number"), p.real("array.pitch_m"));
  c.multipath = read_multipath(p);
  c.spad.dead_time_s = p.real("spad.dead_time_s");
  c.spad.afterpulse_probability = p.real("spad.afterpulse_probability");
  c.spad.afterpulse_time_constant_s = p.real("spad.afterpulse_time_constant_s");
  c.spad.jitter_sigma_s = p.real("spad.jitter_sigma_s");

  c.laser.wavelength_m = p.real("laser.wavelength_m");
  c.laser.pulse_fwhm_s = p.real("laser.pulse_fwhm_s");
  c.laser.sigma_per_fwhm = p.real("laser.sigma_per_fwhm");
  c.laser.repetition_rate_Hz = p.real("laser.repetition_rate_Hz");

  c.tdc.lsb_s = p.real("tdc.lsb_s");
  c.tdc.bits = static_cast<int>(p.integer("tdc.bits"));
  c.tdc.full_range_s = p.real("tdc.full_range_s");
  c.tdc.dnl_rms_lsb = p.real("tdc.dnl_rms_lsb");
  c.tdc.inl_rms_lsb = p.real("tdc.inl_rms_lsb");
  c.tdc.nonlinearity_seed = p.integer("tdc.nonlinearity_seed");
  c.tdc.columns_per_tdc = static_cast<int>(p.integer("tdc.columns_per_tdc"));
  c.tdc.neighbour_rate_fraction = p.real("tdc.neighbour_rate_fraction");
  c.tdc.busy_time_s = p.real("tdc.busy_time_s");

  c.histogram.integration_time_s = p.real("histogram.integration_time_s");
  c.histogram.peak_window_bins = static_cast<int>(p.integer("histogram.peak_window_bins"));
  c.histogram.coates_correction = p.boolean("histogram.coates_correction");
  c.histogram.subtract_background = p.boolean("histogram.subtract_background");
  c.histogram.readout_word_rate_Hz = p.real("histogram.readout_word_rate_Hz");

  auto& e = c.evaluation;
  e.signal_min_Hz = p.real("evaluation.signal_min_Hz");
  e.signal_max_Hz = p.real("evaluation.signal_max_Hz");
  e.signal_points = static_cast<int>(p.integer("evaluation.signal_points"));
  e.background_min_Hz = p.real("evaluation.background_min_Hz");
  e.background_max_Hz = p.real("evaluation.background_max_Hz");
  e.background_points = static_cast<int>(p.integer("evaluation.background_points"));
  e.frames_averaged = static_cast<int>(p.integer("evaluation.frames_averaged"));
  e.distance_m = p.real("evaluation.distance_m");
  e.distance_min_m = p.real("evaluation.distance_min_m");
  e.distance_max_m = p.real("evaluation.distance_max_m");
  e.distance_points = static_cast<int>(p.integer("evaluation.distance_points"));
  e.detection_sigma = p.real("evaluation.detection_sigma");
  e.min_signal_counts = p.real("evaluation.min_signal_counts");
  e.min_armed_fraction = p.real("evaluation.min_armed_fraction");
  e.reference_signal_Hz = p.real("evaluation.reference_signal_Hz");
  e.reference_background_Hz = p.real("evaluation.reference_background_Hz");
  e.sweep_signal_Hz = p.real("evaluation.sweep_signal_Hz");

  // Cross-key checks.
  const double codes_range_s = c.tdc.lsb_s * std::ldexp(1.0, c.tdc.bits);
  if (c.tdc.full_range_s > codes_range_s * (1 + 1e-9))
    throw UserError(fmt::format("{}: tdc.full_range_s = {:g} exceeds tdc.lsb_s x 2^tdc.bits = {:g}; allowed: "
                                "full_range_s <= lsb_s x 2^bits",
                                p.origin(), c.tdc.full_range_s, codes_range_s),
                    "tdc.full_range_s");
  const double period_s = 1.0 / c.laser.repetition_rate_Hz;
  if (period_s / c.tdc.lsb_s > 1e5)
    throw UserError(fmt::format("{}: laser period / tdc.lsb_s = {:g} bins per cycle; allowed: <= 1e5 "
                                "(lower tdc.lsb_s or raise laser.repetition_rate_Hz)",
                                p.origin(), period_s / c.tdc.lsb_s),
                    "tdc.lsb_s");
  check_order(p, "evaluation.signal_min_Hz", e.signal_min_Hz, "evaluation.signal_max_Hz", e.signal_max_Hz);
  check_order(p, "evaluation.background_min_Hz", e.background_min_Hz, "evaluation.background_max_Hz",
              e.background_max_Hz);
  check_order(p, "evaluation.distance_min_m", e.distance_min_m, "evaluation.distance_max_m", e.distance_max_m);
  const double window_m = 299792458.0 * std::min(period_s, c.tdc.full_range_s) / 2;
  if (e.distance_max_m >= window_m || e.distance_m >= window_m)
    throw UserError(
        fmt::format("{}: evaluation.distance_max_m = {:g} / evaluation.distance_m = {:g} must stay below "
                    "the unambiguous range c min(1 / laser.repetition_rate_Hz, tdc.full_range_s) / 2 = {:g} m",
                    p.origin(), e.distance_max_m, e.distance_m, window_m),
        "evaluation.distance_max_m");
  return c;
}

long long laser_cycles_per_row(const TofSpadConfig& cfg) {
  return std::llround(cfg.histogram.integration_time_s * cfg.laser.repetition_rate_Hz);
}

double tdc_clock_Hz(const TofSpadConfig& cfg) { return 1.0 / cfg.tdc.lsb_s; }

long long cycles_per_histogram_word(const TofSpadConfig& cfg) {
  return static_cast<long long>(std::ceil(tdc_clock_Hz(cfg) / cfg.histogram.readout_word_rate_Hz - 1e-9));
}

}  // namespace rangesim
