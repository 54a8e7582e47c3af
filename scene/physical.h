#pragma once
// What every sensor makes of a physical scene, through its radiometry (core/radiometry.h): the
// ambient light and the active source as optical power on one pixel, then in the sensor's own
// unit; and any target shape as a depth map at the sensor's pixel grid. docs/radiometry.md has the
// derivation and a hand-worked example per sensor (tests/simulate/test_radiometry.cpp checks them).
//
//   ambient in the filter band at the target  E_band = E_lambda(lux, spectrum) x filter bandwidth
//   on one pixel (camera equation, Lambertian target of reflectance rho, on-axis, lossless lens):
//     P_bg = rho E_band / (4 F#^2) x pitch^2 x fill factor
//   source of mean power P at distance z:
//     flood  P_sig = rho P f^2 / (4 F#^2 rows columns z^2) x fill factor       (the field of view lit)
//     spot   the same with the spot's rows x columns instead of the array's   (uniform in the spot)
//     sheet  light-section: the row's power P / rows over a Gaussian stripe of sigma pixels, at its
//            peak rho P f^2 / (4 F#^2 rows sigma sqrt(2 pi) z^2) x fill factor; a time-of-flight
//            sensor sees a sheet scanned over its frame as a flood
//   native = native_per_W x P_bg  and  native_per_W x P_sig / signal_duty  (the on-time value)
#include <string>
#include <vector>

#include "core/radiometry.h"
#include "scene/scene.h"

namespace rangesim::scene {

// The light of a scene in one sensor's unit.
struct NativeLight {
  std::string unit;                    // "V", "A", "Hz"
  double wavelength_m = 0;             // band centre used (the scene's, else the sensor's, else 850 nm)
  double ambient_W_per_m2_nm = 0;      // spectral irradiance at the target at that wavelength
  double ambient_in_band_W_per_m2 = 0; // ... times the filter bandwidth
  double background_pixel_W = 0;       // ambient power on one pixel's photosensitive area
  double background = 0;               // ... in the native unit
  double signal_pixel_W_m2 = 0;        // source power on one lit pixel (peak for a sheet) times z^2
  double signal_z2 = 0;                // native signal times z^2 (m^2)
  int spot_first_row = 0, spot_rows = 0, spot_first_column = 0, spot_columns = 0;  // lit pixels
  double signal_at(double z_m) const { return signal_z2 / (z_m * z_m); }
};

// Ambient light in the filter band, per lux (W/m2/lux) for the scene's spectrum, filter and the
// wavelength native_light would use for `r`.
double band_wavelength_m(const PhysicalLight& l, const SensorRadiometry& r);

// The scene's physical light in the sensor's unit. Throws UserError (naming the file, the key and
// the allowed range) for a spot beam outside the array. Appends notes (beam shapes the sensor
// treats differently) to `notes`.
NativeLight native_light(const Scene& s, const SensorRadiometry& r, std::vector<std::string>* notes = nullptr);

// The physical axes of `evaluate` and `compare`: native background per lux of the scene's ambient
// spectrum, and native signal per watt of source power at distance z (the scene's reflectance,
// beam, filter and camera).
double native_background_per_lux(const Scene& s, const SensorRadiometry& r);
double native_signal_per_W(const Scene& s, const SensorRadiometry& r, double z_m);

// The target as a depth map at a rows x columns pixel grid of pitch `pitch_m` behind a lens of
// focal length `focal_length_m` (pinhole at the origin looking along z): plane, tilted plane, step
// (any of its edge forms) or the scene's own depth map resampled. Throws UserError when the tilt
// turns the plane away from a pixel's ray.
std::vector<double> depth_grid_m(const Scene& s, int rows, int columns, double pitch_m, double focal_length_m);
// A copy of the scene with its target as such a depth map at the sensor's grid (shape DepthMap).
Scene rasterised(const Scene& s, const SensorRadiometry& r);

// "note: ..." lines for stderr (and the summary's scene_notes).
std::string notes_text(const std::vector<std::string>& notes, const std::string& command);

}  // namespace rangesim::scene
