// tof-spad's radiometry (core/radiometry.h): optical power on the active area -> count rate
// n = PDE P lambda / (h c), PDE-weighted photons per second before dead-time losses (the unit of
// the preset's rates); the signal is the mean count rate of the pulsed laser.
#include <fmt/format.h>

#include "core/physics.h"
#include "core/radiometry.h"
#include "core/tof_spad/config.h"

namespace rangesim {

SensorRadiometry tof_spad_radiometry(const ParamSet& p) {
  const TofSpadConfig c = tof_spad_from_params(p);
  SensorRadiometry r;
  r.unit = "Hz";
  r.quantity = "count rate";
  r.rows = c.array.rows;
  r.columns = c.array.columns;
  r.pitch_m = c.array.pitch_m;
  r.focal_length_m = c.array.focal_length_m;
  r.f_number = c.array.f_number;
  r.fill_factor = c.spad.fill_factor;
  r.wavelength_m = c.laser.wavelength_m;
  r.signal_duty = 1;  // a count rate is a mean over the laser cycles
  const double photon_J = phys::kPlanck_J_s * phys::kSpeedOfLight_m_per_s / c.laser.wavelength_m;
  r.native_per_W = c.spad.pde / photon_J;
  r.conversion = fmt::format("n = PDE P / (h c / lambda) = {:g} x P / {:.4g} J = {:.4g} Hz/W x P", c.spad.pde, photon_J,
                             r.native_per_W);
  r.distance_key = "evaluation.distance_m";
  return r;
}

}  // namespace rangesim
