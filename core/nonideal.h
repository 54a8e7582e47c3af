#pragma once
// Non-idealities a real chip has and the ideal models leave out (docs/model-limits.md), as
// configuration shared by the sensors that model them: the fixed pattern of a chip (PRNU, DSNU,
// drawn once per chip from a seed), the optics' point spread and the pixels' crosstalk, the
// temperature law of the dark signal and a second return (multipath, time-of-flight only).
// Each sensor declares the keys it uses in its schema (core/<sensor>/schema.cpp) through the
// spec helpers below, so the unit, range and meaning are written once; the sensor's config reads
// them with the readers below.
#include <cstdint>
#include <initializer_list>
#include <string>
#include <vector>

#include "core/params.h"

namespace rangesim {

// Fixed pattern of one chip: every pixel's gain and dark signal differ from the mean by a draw
// that is the same in every frame (a chip is made once), keyed by `seed`.
struct FixedPatternConfig {
  double prnu_fraction = 0;            // photo-response non-uniformity: rms relative gain spread
  double dsnu_rms = 0;                 // dark-signal non-uniformity: rms in the sensor's unit (A or Hz)
  double tap_mismatch_fraction = 0;    // two-tap pixels: rms relative gain spread of each tap
  double comparator_offset_rms_V = 0;  // comparator pixels: rms offset at the comparator input
  std::uint64_t seed = 1;              // the chip
  bool any() const {
    return prnu_fraction > 0 || dsnu_rms > 0 || tap_mismatch_fraction > 0 || comparator_offset_rms_V > 0;
  }
};

enum class PsfKind { None, Gaussian, Airy };

// Optical point spread (on the focal plane) and the pixels' electrical/optical crosstalk.
struct BlurConfig {
  PsfKind psf = PsfKind::None;
  double gaussian_sigma_px = 0;   // psf = gaussian: sigma in pixels
  double wavelength_m = 850e-9;   // psf = airy: the light's wavelength
  double f_number = 1.4;          // psf = airy: the lens F#
  double pitch_m = 10e-6;         // psf = airy: the pixel pitch (sigma in pixels)
  double crosstalk_fraction = 0;  // share of a pixel's signal that lands on its 4 neighbours (1/4 each)
  bool any() const { return psf_sigma_px() > 0 || crosstalk_fraction > 0; }
  // The PSF as a Gaussian of this sigma on the focal plane, in pixels. Airy: the Gaussian that
  // best fits the Airy pattern's core, sigma = 0.42 lambda F# ("Gaussian approximations of
  // fluorescence microscope point-spread function models", Zhang, Zerubia, Olivo-Marin, 2007:
  // sigma = 0.21 lambda / NA with NA = 1 / (2 F#)).
  double psf_sigma_px() const;
};

// Dark current / dark count rate at the sensor temperature T: the preset's value is the one at
// T_ref, and it doubles every `doubling_K` (the usual empirical law of thermal generation).
struct DarkTemperatureConfig {
  double reference_K = 300;
  double doubling_K = 7;
  double scale(double temperature_K) const;  // 2^((T - T_ref) / doubling)
};

// A second return for time-of-flight sensors: every pixel also sees its own surface again over
// a longer path (a reflection via another surface), at a fraction of the direct signal.
struct MultipathConfig {
  double relative_amplitude = 0;  // second return / direct, in the sensor's signal unit (0: off)
  double extra_path_m = 1.0;      // extra round-trip path of the second return
  bool on() const { return relative_amplitude > 0; }
};

// Schema entries (unit in the key, range, meaning); `dsnu_unit` is the sensor's signal unit
// ("A" or "Hz"), `dsnu_max` its largest meaningful spread.
std::vector<ParamSpec> fixed_pattern_specs(const std::string& dsnu_unit, double dsnu_max, bool two_tap,
                                           bool comparator);
std::vector<ParamSpec> blur_specs(bool own_wavelength);
std::vector<ParamSpec> dark_temperature_specs();
std::vector<ParamSpec> multipath_specs();

// `schema` with the entries of `extra` appended (a sensor's schema plus the helpers' entries).
ParamSchema with_specs(ParamSchema schema, std::initializer_list<std::vector<ParamSpec>> extra);

// Readers of a validated preset; `dsnu_unit` as declared. `wavelength_m`, `f_number`, `pitch_m`
// come from the sensor's own keys (airy); with `own_wavelength` blur.wavelength_m is read.
FixedPatternConfig read_fixed_pattern(const ParamSet& p, const std::string& dsnu_unit, bool two_tap, bool comparator);
BlurConfig read_blur(const ParamSet& p, double wavelength_m, double f_number, double pitch_m);
DarkTemperatureConfig read_dark_temperature(const ParamSet& p);
MultipathConfig read_multipath(const ParamSet& p);

}  // namespace rangesim
