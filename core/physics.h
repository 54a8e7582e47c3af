#pragma once
// Physical constants (CODATA 2018 exact values where defined).

namespace rangesim::phys {

inline constexpr double kElementaryCharge_C = 1.602176634e-19;
inline constexpr double kBoltzmann_J_per_K = 1.380649e-23;
inline constexpr double kSpeedOfLight_m_per_s = 299792458.0;
inline constexpr double kPlanck_J_s = 6.62607015e-34;
// sigma / FWHM of a Gaussian: 1 / (2 sqrt(2 ln 2)). The thesis writes 0.45 (a typo).
inline constexpr double kGaussSigmaPerFwhm = 0.42466090014400953;

}  // namespace rangesim::phys
