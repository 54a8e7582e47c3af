// ls-demodulation's radiometry (core/radiometry.h): optical power on the photodiode ->
// photocurrent I = R P; the signal is the beam-on current (mean over the modulation / duty).
#include <fmt/format.h>

#include "core/ls_demodulation/config.h"
#include "core/radiometry.h"

namespace rangesim {

SensorRadiometry ls_demodulation_radiometry(const ParamSet& p) {
  const LsDemodulationConfig c = ls_demodulation_from_params(p);
  SensorRadiometry r;
  r.unit = "A";
  r.quantity = "photocurrent";
  r.rows = c.pixel.rows;
  r.columns = c.pixel.columns;
  r.pitch_m = c.pixel.pitch_m;
  r.focal_length_m = c.optics.focal_length_m;
  r.f_number = c.optics.f_number;
  r.fill_factor = c.pixel.fill_factor;
  r.stripe_sigma_px = c.spot.fwhm_px * c.spot.sigma_per_fwhm;
  r.signal_duty = c.modulation.source_duty_cycle;
  r.native_per_W = c.pixel.responsivity_A_per_W;
  r.conversion = fmt::format("I = R P = {:g} A/W x P; signal: beam-on current = mean / {:g} (modulation duty)",
                             r.native_per_W, r.signal_duty);
  r.distance_key = "optics.distance_m";
  return r;
}

}  // namespace rangesim
