#include "scene/physical.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>
#include <memory>

#include "core/user_error.h"
#include "scene/light.h"

namespace rangesim::scene {

namespace {
constexpr double kPi = 3.14159265358979323846;
constexpr double kDefaultWavelength_m = 850e-9;

double ambient_spectral(const PhysicalLight& l, double wavelength_m, double lux) {
  if (l.spectral_irradiance_W_per_m2_nm >= 0) return l.spectral_irradiance_W_per_m2_nm;
  return spectral_irradiance_W_per_m2_nm(l.spectrum, lux, wavelength_m);
}

// Source power on one lit pixel (W m^2: divide by z^2) for 1 W of mean source power.
double signal_pixel_W_m2_per_W(const Scene& s, const SensorRadiometry& r, const NativeLight& n) {
  const double k = s.reflectance * r.focal_length_m * r.focal_length_m * r.fill_factor / (4 * r.f_number * r.f_number);
  const bool light_section = r.stripe_sigma_px > 0;
  if (s.light.beam == BeamShape::Spot && !light_section) return k / (n.spot_rows * static_cast<double>(n.spot_columns));
  if (light_section) return k / (r.rows * r.stripe_sigma_px * std::sqrt(2 * kPi));
  return k / (r.rows * static_cast<double>(r.columns));
}

SensorRadiometry with_camera(const Scene& s, SensorRadiometry r) {
  if (s.has("camera.f_number")) r.f_number = s.get("camera.f_number", r.f_number);
  return r;
}

}  // namespace

double band_wavelength_m(const PhysicalLight& l, const SensorRadiometry& r) {
  return l.wavelength_m > 0 ? l.wavelength_m : r.wavelength_m > 0 ? r.wavelength_m : kDefaultWavelength_m;
}

NativeLight native_light(const Scene& s, const SensorRadiometry& radiometry, std::vector<std::string>* notes) {
  const SensorRadiometry r = with_camera(s, radiometry);
  const PhysicalLight& l = s.light;
  NativeLight n;
  n.unit = r.unit;
  n.wavelength_m = band_wavelength_m(l, r);
  n.ambient_W_per_m2_nm = ambient_spectral(l, n.wavelength_m, l.illuminance_lux);
  n.ambient_in_band_W_per_m2 = n.ambient_W_per_m2_nm * l.filter_bandwidth_m * 1e9;
  n.background_pixel_W =
      s.reflectance * n.ambient_in_band_W_per_m2 / (4 * r.f_number * r.f_number) * r.pitch_m * r.pitch_m * r.fill_factor;
  n.background = r.native_per_W * n.background_pixel_W;
  // The lit pixels: the spot's footprint, else the whole array.
  n.spot_rows = r.rows, n.spot_columns = r.columns;
  const bool light_section = r.stripe_sigma_px > 0;
  if (l.beam == BeamShape::Spot) {
    const auto get = [&](const char* key, int def, int lo, int hi) {
      const double v = s.get(key, def);
      if (v < lo || v > hi)
        throw UserError(fmt::format("{}: {} = {:g} puts the spot outside the {} x {} array of {}; allowed {} <= value "
                                    "<= {}",
                                    s.file, key, v, r.rows, r.columns, s.sensor, lo, hi));
      return static_cast<int>(v);
    };
    n.spot_rows = get("beam.rows", std::min(8, r.rows), 1, r.rows);
    n.spot_first_row = get("beam.first_row", (r.rows - n.spot_rows) / 2, 0, r.rows - n.spot_rows);
    n.spot_columns = get("beam.columns", std::min(8, r.columns), 1, r.columns);
    n.spot_first_column = get("beam.first_column", (r.columns - n.spot_columns) / 2, 0, r.columns - n.spot_columns);
    if (notes && light_section)
      notes->push_back(fmt::format("{}: source.beam = \"spot\": {} is a light-section sensor; the spot's power is "
                                   "formed into its sheet beam",
                                   s.file, s.sensor));
  } else if (l.beam == BeamShape::Flood && light_section && notes) {
    notes->push_back(fmt::format(
        "{}: source.beam = \"flood\": {} is a light-section sensor; the flood's power is formed into its sheet beam",
        s.file, s.sensor));
  } else if (l.beam == BeamShape::Sheet && !light_section && notes) {
    notes->push_back(fmt::format("{}: source.beam = \"sheet\": {} sees the sheet scanned over its frame as a flood of "
                                 "the same mean power",
                                 s.file, s.sensor));
  }
  n.signal_pixel_W_m2 = l.source_power_W * signal_pixel_W_m2_per_W(s, r, n);
  n.signal_z2 = r.native_per_W * n.signal_pixel_W_m2 / r.signal_duty;
  return n;
}

double native_background_per_lux(const Scene& s, const SensorRadiometry& r) {
  Scene one = s;
  one.light.illuminance_lux = 1.0;
  one.light.spectral_irradiance_W_per_m2_nm = -1;
  return native_light(one, r).background;
}

double native_signal_per_W(const Scene& s, const SensorRadiometry& r, double z_m) {
  Scene one = s;
  one.light.source_power_W = 1.0;
  return native_light(one, r).signal_at(z_m);
}

std::vector<double> depth_grid_m(const Scene& s, int rows, int columns, double pitch_m, double focal_length_m) {
  std::vector<double> z(static_cast<std::size_t>(rows) * columns);
  if (s.shape == TargetShape::DepthMap) return s.depth_map->resample(rows, columns);
  const double cy = 0.5 * (rows - 1), cx = 0.5 * (columns - 1);
  const double tx = std::tan(s.tilt_x_rad), ty = std::tan(s.tilt_y_rad);
  for (int r = 0; r < rows; ++r)
    for (int c = 0; c < columns; ++c) {
      const double xr = (c - cx) * pitch_m / focal_length_m, yr = (r - cy) * pitch_m / focal_length_m;
      double d = s.distance_m;
      if (s.shape == TargetShape::Tilted) {
        // z = l0 + x tan(tx) + y tan(ty) on the ray (x, y) = z (xr, yr).
        const double den = 1 - xr * tx - yr * ty;
        if (!(den > 0))
          throw UserError(fmt::format("{}: target.tilt_x_rad / target.tilt_y_rad turn the plane away from pixel "
                                      "({}, {}) of a {} x {} array; allowed: tilts whose plane faces every pixel",
                                      s.file, r, c, rows, columns));
        d = s.distance_m / den;
      } else if (s.shape == TargetShape::Objects) {
        const double u = (c + 0.5) / columns, v = (r + 0.5) / rows;  // the pixel centre in the field of view
        for (const auto& o : s.objects)
          if (u >= o.left && u < o.right && v >= o.top && v < o.bottom) d = std::min(d, o.distance_m);
      } else if (s.shape == TargetShape::Step) {
        if (s.has("target.step_y_m"))
          d = s.near_distance_m * yr > s.step_y_m ? s.near_distance_m : s.distance_m;
        else if (s.has("target.step_column") || s.has("target.step_distance_m"))
          d = c < s.get("target.step_column", columns / 2) ? s.distance_m : s.get("target.step_distance_m", s.distance_m);
        else  // a column fraction (default 0.5) of near face on the left
          d = c < s.get("target.step_column_fraction", 0.5) * columns ? s.near_distance_m : s.distance_m;
      }
      z[static_cast<std::size_t>(r) * columns + c] = d;
    }
  return z;
}

Scene rasterised(const Scene& s, const SensorRadiometry& r) {
  Scene out = s;
  auto map = std::make_shared<DepthMap>();
  map->file = s.file + " (" + shape_name(s.shape) + ", rasterised)";
  map->width = r.columns;
  map->height = r.rows;
  map->depth_m = depth_grid_m(s, r.rows, r.columns, r.pitch_m, r.focal_length_m);
  out.shape = TargetShape::DepthMap;
  out.depth_map = map;
  out.distance_m = *std::min_element(map->depth_m.begin(), map->depth_m.end());
  return out;
}

std::string notes_text(const std::vector<std::string>& notes, const std::string& command) {
  std::string t;
  for (const auto& n : notes) t += fmt::format("rangesim {}: note: {}\n", command, n);
  return t;
}

}  // namespace rangesim::scene
