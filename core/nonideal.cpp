#include "core/nonideal.h"

#include <cmath>

namespace rangesim {

double BlurConfig::psf_sigma_px() const {
  switch (psf) {
    case PsfKind::None: return 0;
    case PsfKind::Gaussian: return gaussian_sigma_px;
    case PsfKind::Airy: return 0.42 * wavelength_m * f_number / pitch_m;
  }
  return 0;
}

double DarkTemperatureConfig::scale(double temperature_K) const {
  return std::exp2((temperature_K - reference_K) / doubling_K);
}

ParamSchema with_specs(ParamSchema schema, std::initializer_list<std::vector<ParamSpec>> extra) {
  for (const auto& v : extra) schema.params.insert(schema.params.end(), v.begin(), v.end());
  return schema;
}

std::vector<ParamSpec> fixed_pattern_specs(const std::string& dsnu_unit, double dsnu_max, bool two_tap,
                                           bool comparator) {
  using K = ParamKind;
  std::vector<ParamSpec> s{
      {"fixed_pattern.prnu_fraction", K::Real, "", 0, 0.5, false,
       "photo-response non-uniformity: rms relative gain spread over the pixels, the same every frame (0 = off)"},
      {"fixed_pattern.dsnu_rms_" + dsnu_unit, K::Real, dsnu_unit, 0, dsnu_max, false,
       "dark-signal non-uniformity: rms spread of the dark signal over the pixels, the same every frame (0 = off)"},
      {"fixed_pattern.seed", K::Integer, "", 0, 9.007199254740992e15, false,
       "the chip: key of the fixed-pattern draws (another seed, another chip)"},
  };
  if (two_tap)
    s.push_back({"fixed_pattern.tap_mismatch_fraction", K::Real, "", 0, 0.5, false,
                 "rms relative gain spread of each tap (FD1, FD2) of a pixel: charge transfer and conversion gain "
                 "mismatch, not cancelled by the ratio (0 = off)"});
  if (comparator)
    s.push_back({"fixed_pattern.comparator_offset_rms_V", K::Real, "V", 0, 1, false,
                 "rms offset of each pixel's comparator at its input, the same every frame (0 = off)"});
  return s;
}

std::vector<ParamSpec> blur_specs(bool own_wavelength) {
  using K = ParamKind;
  std::vector<ParamSpec> s{
      {"blur.psf",
       K::Text,
       "",
       0,
       0,
       false,
       "optical point spread on the focal plane: none, gaussian (blur.gaussian_sigma_px) or airy (diffraction "
       "of the lens: the Gaussian of sigma 0.42 lambda F#)",
       {"none", "gaussian", "airy"}},
      {"blur.gaussian_sigma_px", K::Real, "px", 0, 20, false, "psf = gaussian: sigma of the point spread, in pixels"},
      {"blur.crosstalk_fraction", K::Real, "", 0, 0.5, false,
       "share of a pixel's light-induced signal collected by its four neighbours (a quarter each; 0 = off)"},
  };
  if (own_wavelength)
    s.push_back({"blur.wavelength_m", K::Real, "m", 0, 1e-5, true, "psf = airy: wavelength of the light"});
  return s;
}

std::vector<ParamSpec> dark_temperature_specs() {
  using K = ParamKind;
  return {
      {"dark.reference_temperature_K", K::Real, "K", 0, 500, true,
       "temperature at which the preset's dark current (dark count rate) is given"},
      {"dark.doubling_temperature_K", K::Real, "K", 0, 100, true,
       "the dark signal doubles every this many kelvin above the reference (thermal generation)"},
  };
}

std::vector<ParamSpec> multipath_specs() {
  using K = ParamKind;
  return {
      {"multipath.relative_amplitude", K::Real, "", 0, 10, false,
       "second return (multipath) / direct return on every pixel (0 = single return)"},
      {"multipath.extra_path_m", K::Real, "m", 0, 1e4, false,
       "extra round-trip path of the second return (its delay is this / c)"},
  };
}

FixedPatternConfig read_fixed_pattern(const ParamSet& p, const std::string& dsnu_unit, bool two_tap, bool comparator) {
  FixedPatternConfig f;
  f.prnu_fraction = p.real("fixed_pattern.prnu_fraction");
  f.dsnu_rms = p.real("fixed_pattern.dsnu_rms_" + dsnu_unit);
  f.seed = static_cast<std::uint64_t>(p.integer("fixed_pattern.seed"));
  if (two_tap) f.tap_mismatch_fraction = p.real("fixed_pattern.tap_mismatch_fraction");
  if (comparator) f.comparator_offset_rms_V = p.real("fixed_pattern.comparator_offset_rms_V");
  return f;
}

BlurConfig read_blur(const ParamSet& p, double wavelength_m, double f_number, double pitch_m) {
  BlurConfig b;
  const std::string& psf = p.text("blur.psf");
  b.psf = psf == "gaussian" ? PsfKind::Gaussian : psf == "airy" ? PsfKind::Airy : PsfKind::None;
  b.gaussian_sigma_px = p.real("blur.gaussian_sigma_px");
  b.crosstalk_fraction = p.real("blur.crosstalk_fraction");
  b.wavelength_m = p.has("blur.wavelength_m") ? p.real("blur.wavelength_m") : wavelength_m;
  b.f_number = f_number;
  b.pitch_m = pitch_m;
  return b;
}

DarkTemperatureConfig read_dark_temperature(const ParamSet& p) {
  return {p.real("dark.reference_temperature_K"), p.real("dark.doubling_temperature_K")};
}

MultipathConfig read_multipath(const ParamSet& p) {
  return {p.real("multipath.relative_amplitude"), p.real("multipath.extra_path_m")};
}

}  // namespace rangesim
