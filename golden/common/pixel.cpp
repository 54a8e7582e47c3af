#include "golden/common/pixel.h"

#include <cmath>

#include "core/physics.h"

namespace rangesim::golden {

double voltage_from_current_V(double current_A, double time_s, double capacitance_F) {
  return current_A * time_s / capacitance_F;
}

double current_from_voltage_A(double voltage_V, double time_s, double capacitance_F) {
  return voltage_V * capacitance_F / time_s;
}

double dark_voltage_V(const PixelConfig& pixel) {
  return voltage_from_current_V(pixel.dark_current_A, pixel.integration_time_s, pixel.pd_capacitance_F);
}

double electrons_per_volt(const PixelConfig& pixel) { return pixel.pd_capacitance_F / phys::kElementaryCharge_C; }

double ktc_noise_V(const PixelConfig& pixel) {
  return std::sqrt(phys::kBoltzmann_J_per_K * pixel.temperature_K / pixel.pd_capacitance_F);
}

double static_noise_V(const PixelConfig& pixel) { return std::hypot(ktc_noise_V(pixel), pixel.read_noise_V); }

double pixel_swing_V(double signal_V, double profile, double background_V, double dark_V, double t_over_T) {
  return (signal_V * profile + background_V + dark_V) * t_over_T;
}

double output_voltage_V(const PixelConfig& pixel, double swing_V) { return pixel.source_follower_gain * swing_V; }

bool saturates(const PixelConfig& pixel, double swing_V) { return swing_V > pixel.saturation_voltage_V; }

}  // namespace rangesim::golden
