// tof-lockin's radiometry (core/radiometry.h): optical power on the photogate -> photocurrent
// I = R P; the signal is the current during the light pulse (mean / duty cycle).
#include <fmt/format.h>

#include "core/radiometry.h"
#include "core/tof_lockin/config.h"

namespace rangesim {

SensorRadiometry tof_lockin_radiometry(const ParamSet& p) {
  const TofLockinConfig c = tof_lockin_from_params(p);
  SensorRadiometry r;
  r.unit = "A";
  r.quantity = "photocurrent";
  r.rows = c.pixel.rows;
  r.columns = c.pixel.columns;
  r.pitch_m = c.pixel.pitch_m;
  r.focal_length_m = c.optics.focal_length_m;
  r.f_number = c.optics.f_number;
  r.fill_factor = c.pixel.fill_factor;
  r.wavelength_m = c.source.wavelength_m;
  r.signal_duty = c.source.duty_cycle;
  r.native_per_W = c.pixel.responsivity_A_per_W;
  r.conversion = fmt::format("I = R P = {:g} A/W x P; signal: current during the pulse = mean / {:g} (duty cycle)",
                             r.native_per_W, r.signal_duty);
  r.distance_key = "evaluation.distance_m";
  return r;
}

}  // namespace rangesim
