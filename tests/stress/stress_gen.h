#pragma once
// RapidCheck generators of extreme but legal ls-conventional inputs (every value inside the
// preset schema's range, core/ls_conventional/schema.cpp), shared by the stress properties.
//
// The cost of one closed-form operating point grows as samplings^3 x activation window (exact
// 1-bit moments) and samplings x 2^adc_bits (multi-bit codes); the generators keep every legal
// extreme of each axis but cap the product so that ~100 cases per property run in seconds (the
// full-size corners have their own timed tests in test_ls_conventional_stress.cpp).
#include <rapidcheck.h>

#include <algorithm>
#include <cmath>
#include <ostream>

#include "core/ls_conventional/config.h"

namespace rangesim {

// Printed by RapidCheck with a failing case: every field, so the case can be pasted into a test.
inline std::ostream& operator<<(std::ostream& os, ThresholdMode m) {
  return os << (m == ThresholdMode::Fixed ? "Fixed" : "Tracking");
}
inline std::ostream& operator<<(std::ostream& os, const LsConventionalConfig& c) {
  os.precision(17);
  return os << "{integration_time_s=" << c.pixel.integration_time_s << " pd_capacitance_F=" << c.pixel.pd_capacitance_F
            << " source_follower_gain=" << c.pixel.source_follower_gain
            << " saturation_voltage_V=" << c.pixel.saturation_voltage_V << " dark_current_A=" << c.pixel.dark_current_A
            << " temperature_K=" << c.pixel.temperature_K << " read_noise_V=" << c.pixel.read_noise_V
            << " columns=" << c.pixel.columns << " pitch_m=" << c.pixel.pitch_m << " fwhm_px=" << c.spot.fwhm_px
            << " sigma_per_fwhm=" << c.spot.sigma_per_fwhm << " threshold_mode=" << c.comparator.threshold_mode
            << " threshold_above_background_V=" << c.comparator.threshold_above_background_V
            << " fixed_threshold_V=" << c.comparator.fixed_threshold_V << " adc_bits=" << c.comparator.adc_bits
            << " false_activation_max=" << c.comparator.false_activation_max
            << " samplings=" << c.multisampling.samplings << " focal_length_m=" << c.optics.focal_length_m
            << " baseline_m=" << c.optics.baseline_m << " distance_m=" << c.optics.distance_m
            << " subpixel_points=" << c.grid.subpixel_points << "}";
}

}  // namespace rangesim

namespace rangesim::stress {

// Log-uniform double in [lo, hi] (lo > 0), 2^20 steps; shrinks towards lo.
inline rc::Gen<double> log_uniform(double lo, double hi) {
  return rc::gen::map(rc::gen::inRange<int>(0, (1 << 20) + 1), [lo, hi](int i) {
    if (i >= (1 << 20)) return hi;
    // In log space: hi / lo overflows for spans like 1e-300 .. 1e300.
    return std::exp(std::log(lo) + (std::log(hi) - std::log(lo)) * (i / double(1 << 20)));
  });
}

// Log-uniform, or exactly 0 one time in `zero_one_in`.
inline rc::Gen<double> log_uniform_or_zero(double lo, double hi, int zero_one_in = 8) {
  return rc::gen::weightedOneOf<double>({{1, rc::gen::just(0.0)}, {zero_one_in - 1, log_uniform(lo, hi)}});
}

// Samplings 1..64 with the powers of two and the ends over-represented.
inline rc::Gen<int> samplings_gen() {
  return rc::gen::oneOf(rc::gen::inRange(1, 65), rc::gen::element(1, 2, 4, 8, 16, 32, 64));
}

// Signal or background swing at the end of integration: 1e-7 .. 1e2 V (180 dB; the grid allows
// (0, 100] V).
inline rc::Gen<double> volts_gen() { return log_uniform(1e-7, 1e2); }

struct Limits {
  double capacitance_max_F = 1e-12;  // 1 nF (the schema's max) is in the timed tests only
  int columns_max = 48;
  bool adaptive = false;  // a quarter of the cases take the adaptive average (subpixel_tolerance 1e-3)
};

// A complete legal configuration; the fixed rule of grid.subpixel_points 1..3 positions (cheap,
// and the same positions at every point, which the monotonicity properties compare).
inline rc::Gen<LsConventionalConfig> config_gen(Limits lim = {}) {
  return rc::gen::exec([lim] {
    LsConventionalConfig c;
    c.pixel.integration_time_s = *log_uniform(1e-9, 1.0);
    c.pixel.pd_capacitance_F = *log_uniform(1e-18, lim.capacitance_max_F);
    c.pixel.source_follower_gain = *log_uniform(1e-3, 10.0);
    c.pixel.saturation_voltage_V = *log_uniform(1e-3, 10.0);
    c.pixel.dark_current_A = *log_uniform_or_zero(1e-18, 1e-9);
    c.pixel.temperature_K = *log_uniform(1e-3, 500.0);
    c.pixel.read_noise_V = *log_uniform_or_zero(1e-9, 1.0);
    c.pixel.columns = *rc::gen::oneOf(rc::gen::inRange(1, lim.columns_max + 1), rc::gen::element(1, 2, 3));
    c.pixel.rows = 1;
    c.pixel.pitch_m = *log_uniform(1e-7, 1e-3);
    c.spot.fwhm_px = *log_uniform(1e-3, 100.0);
    c.spot.sigma_per_fwhm = *rc::gen::oneOf(rc::gen::element(0.42466090014400953, 0.45), log_uniform(1e-3, 1.0));
    c.comparator.threshold_mode = *rc::gen::element(ThresholdMode::Tracking, ThresholdMode::Fixed);
    c.comparator.threshold_above_background_V = *log_uniform(1e-6, 10.0);
    c.comparator.fixed_threshold_V = *log_uniform(1e-6, 10.0);
    c.comparator.adc_bits = *rc::gen::oneOf(rc::gen::inRange(1, 17), rc::gen::just(1));
    c.comparator.false_activation_max = *log_uniform(1e-12, 1.0);
    c.multisampling.samplings = *samplings_gen();
    // Cost caps (see above): shrink the row for many samplings, the samplings for many bits.
    const double n = c.multisampling.samplings;
    c.pixel.columns = std::max(1, std::min(c.pixel.columns, static_cast<int>(4e6 / (n * n * n))));
    while (c.multisampling.samplings > 1 &&
           double(c.multisampling.samplings) * (1 << c.comparator.adc_bits) > (1 << 18))
      c.multisampling.samplings /= 2;
    c.search.columns = c.pixel.columns;
    c.optics.focal_length_m = *log_uniform(1e-4, 10.0);
    c.optics.baseline_m = *log_uniform(1e-4, 100.0);
    c.optics.distance_m = *log_uniform(1e-3, 1e4);
    c.grid.subpixel_points = *rc::gen::inRange(1, 4);
    c.grid.subpixel_tolerance = 0;
    return c;
  });
}

}  // namespace rangesim::stress
