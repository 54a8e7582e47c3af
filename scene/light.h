#pragma once
// Ambient light of a physical scene: illuminance in lux with a named spectrum, turned into the
// spectral irradiance (W/m2/nm) at the active source's wavelength, which is what a narrow-band
// sensor sees of it. docs/radiometry.md derives it and works examples by hand.
//
//   E_v = K_m integral V(lambda) E_e(lambda) dlambda,  K_m = 683 lm/W  (photometry's definition)
//   E_e(lambda) = E_v S(lambda) / (K_m integral V S dlambda)     for a spectrum shape S
//
// Spectra (relative shapes S; the absolute level comes from the illuminance):
//   sunlight   Planck black body at 5778 K (the sun's effective temperature; the atmosphere's
//              absorption bands, e.g. water at 940 nm, are not modelled)
//   halogen    Planck black body at 2856 K (CIE standard illuminant A, a tungsten-halogen lamp)
//   led        white phosphor LED: a blue Gaussian at 450 nm (FWHM 20 nm) plus a phosphor Gaussian at
//              560 nm (FWHM 120 nm) with 2.5x its peak; nothing in the near infrared
// V(lambda) is the CIE 1924 photopic luminosity function in its single-Gaussian approximation
// 1.019 exp(-285.4 (lambda/um - 0.559)^2) (within ~2% of the tabulated function's integral).
#include <string>
#include <vector>

namespace rangesim::scene {

inline constexpr double kLumensPerWatt = 683.0;  // K_m, luminous efficacy at 555 nm (lm/W)

// The spectrum names a scene may use: "sunlight", "halogen", "led".
const std::vector<std::string>& spectrum_names();
bool known_spectrum(const std::string& name);

// Relative spectral shape S(lambda) of a named spectrum (arbitrary scale); lambda in metres.
double spectrum_shape(const std::string& name, double wavelength_m);
// CIE photopic luminosity V(lambda) (the Gaussian approximation above).
double photopic_luminosity(double wavelength_m);
// Luminous efficacy of the spectrum's radiation, K_m integral V S / integral S, in lm/W (the
// integral of S over 200 nm - 3 um).
double luminous_efficacy_lm_per_W(const std::string& name);
// Spectral irradiance (W/m2/nm) at `wavelength_m` of `lux` of the named spectrum.
double spectral_irradiance_W_per_m2_nm(const std::string& name, double lux, double wavelength_m);

}  // namespace rangesim::scene
