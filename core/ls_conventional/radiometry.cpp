// ls-conventional's radiometry (core/radiometry.h): optical power on the photodiode -> swing at
// the end of integration, V = R P t_int / C_pd (thesis eq. 3.1 with I = R P).
#include <cmath>
#include <fmt/format.h>

#include "core/ls_conventional/config.h"
#include "core/radiometry.h"

namespace rangesim {

SensorRadiometry ls_conventional_radiometry(const ParamSet& p) {
  const LsConventionalConfig c = ls_conventional_from_params(p);
  SensorRadiometry r;
  r.unit = "V";
  r.quantity = "swing at the end of integration";
  r.rows = c.pixel.rows;
  r.columns = c.pixel.columns;
  r.pitch_m = c.pixel.pitch_m;
  r.focal_length_m = c.optics.focal_length_m;
  r.f_number = c.optics.f_number;
  r.fill_factor = c.pixel.fill_factor;
  r.stripe_sigma_px = c.spot.fwhm_px * c.spot.sigma_per_fwhm;
  r.signal_duty = 1;  // the sheet beam is on through the integration
  r.native_per_W = c.pixel.responsivity_A_per_W * c.pixel.integration_time_s / c.pixel.pd_capacitance_F;
  r.conversion =
      fmt::format("V = R P t_int / C_pd = {:g} A/W x P x {:g} s / {:g} F = {:.4g} V/W x P",
                  c.pixel.responsivity_A_per_W, c.pixel.integration_time_s, c.pixel.pd_capacitance_F, r.native_per_W);
  r.distance_key = "optics.distance_m";
  return r;
}

}  // namespace rangesim
