#pragma once
// The radiometric part of the sensor interface: what a sensor's preset says about how light on its
// pixels becomes its own signal unit. The physical scene (scene/physical.h) turns lux, watts and
// reflectance into optical power on one pixel; this struct, filled by each sensor from its preset
// (core/<sensor>/radiometry.cpp, registered as SensorInfo::radiometry), turns that power into the
// unit its golden model and clock-level kernels take:
//   ls-conventional   V    swing at the end of integration, V = R P t_int / C_pd  (thesis eq. 3.1)
//   ls-demodulation   A    photocurrent, I = R P (beam-on current for the signal)
//   tof-lockin        A    photocurrent, I = R P (current during the light pulse for the signal)
//   tof-spad          Hz   count rate, n = PDE P lambda / (h c) (before dead-time losses)
// docs/radiometry.md derives the chain and works one example per sensor by hand.
#include <string>

namespace rangesim {

struct SensorRadiometry {
  std::string unit;      // native unit of signal and background: "V", "A" or "Hz"
  std::string quantity;  // what the unit measures, e.g. "swing at the end of integration"
  int rows = 0;          // pixel array
  int columns = 0;
  double pitch_m = 0;         // pixel pitch
  double focal_length_m = 0;  // lens focal length (image scale and field of view)
  double f_number = 0;        // lens F# (camera equation)
  double fill_factor = 0;     // photosensitive share of the pixel area
  double wavelength_m = 0;    // the preset's source wavelength; 0 when its preset has none
  // Light-section sensors: Gaussian sigma of the sheet beam's stripe across a row, in pixels (the
  // spot-peak pixel gets the fraction 1 / (sigma sqrt(2 pi)) of the row's power). 0: a
  // time-of-flight sensor, which sees a scanned sheet as its time mean, a flood.
  double stripe_sigma_px = 0;
  // Fraction of the time the source is on. The scene gives the source's mean optical power; the
  // native signal is its value while the source is on (ls-demodulation: beam-on half period;
  // tof-lockin: during the pulse), i.e. mean / duty. 1 for a continuous signal or a count rate.
  double signal_duty = 1;
  double native_per_W = 0;    // native units per watt on the photosensitive area (linear)
  std::string conversion;     // the conversion with the preset's numbers, one line
  std::string distance_key;   // preset key of the distance its accuracy figures are taken at
};

}  // namespace rangesim
