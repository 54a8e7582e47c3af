#include "scene/light.h"

#include <algorithm>
#include <cmath>
#include <map>

#include "core/physics.h"

namespace rangesim::scene {

namespace {

double planck(double wavelength_m, double temperature_K) {
  const double h = phys::kPlanck_J_s, c = phys::kSpeedOfLight_m_per_s, k = phys::kBoltzmann_J_per_K;
  const double l = wavelength_m;
  return 2 * h * c * c / (l * l * l * l * l) / std::expm1(h * c / (l * k * temperature_K));
}

double gauss(double x, double mu, double fwhm) {
  const double s = fwhm / 2.3548200450309493;
  return std::exp(-0.5 * (x - mu) * (x - mu) / (s * s));
}

// integral of f over [lo, hi] nm with 1 nm steps (trapezoid); the spectra are smooth on that scale.
template <class F>
double integrate_nm(double lo_nm, double hi_nm, const F& f) {
  double sum = 0;
  const int n = static_cast<int>(hi_nm - lo_nm);
  for (int i = 0; i <= n; ++i) sum += (i == 0 || i == n ? 0.5 : 1.0) * f((lo_nm + i) * 1e-9);
  return sum;
}

}  // namespace

const std::vector<std::string>& spectrum_names() {
  static const std::vector<std::string> names = {"sunlight", "halogen", "led"};
  return names;
}

bool known_spectrum(const std::string& name) {
  const auto& n = spectrum_names();
  return std::find(n.begin(), n.end(), name) != n.end();
}

double spectrum_shape(const std::string& name, double wavelength_m) {
  if (name == "sunlight") return planck(wavelength_m, 5778.0);
  if (name == "halogen") return planck(wavelength_m, 2856.0);
  if (name == "led") {
    const double nm = wavelength_m * 1e9;
    return gauss(nm, 450, 20) + 2.5 * gauss(nm, 560, 120);
  }
  return 0;
}

double photopic_luminosity(double wavelength_m) {
  const double um = wavelength_m * 1e6;
  return 1.019 * std::exp(-285.4 * (um - 0.559) * (um - 0.559));
}

namespace {
// integral V S over the visible (360-830 nm), per nm.
double visible_integral(const std::string& name) {
  static std::map<std::string, double> cache;
  static const bool filled = [] {
    for (const auto& n : spectrum_names())
      cache[n] = integrate_nm(360, 830, [&](double l) { return photopic_luminosity(l) * spectrum_shape(n, l); });
    return true;
  }();
  (void)filled;
  return cache.at(name);
}
}  // namespace

double luminous_efficacy_lm_per_W(const std::string& name) {
  const double total = integrate_nm(200, 3000, [&](double l) { return spectrum_shape(name, l); });
  return kLumensPerWatt * visible_integral(name) / total;
}

double spectral_irradiance_W_per_m2_nm(const std::string& name, double lux, double wavelength_m) {
  if (lux <= 0) return 0;
  return lux * spectrum_shape(name, wavelength_m) / (kLumensPerWatt * visible_integral(name));
}

}  // namespace rangesim::scene
