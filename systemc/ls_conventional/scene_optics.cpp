#include "systemc/ls_conventional/scene_optics.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fmt/format.h>

#include "core/user_error.h"
#include "golden/common/pixel.h"
#include "golden/common/spot.h"
#include "scene/physical.h"
#include "systemc/ls_conventional/nonideal_pattern.h"

namespace rangesim::scene {

namespace {
constexpr double kPi = 3.14159265358979323846;
}

Scene ls_conventional_scene(Scene s, const ParamSet& params) {
  const SensorRadiometry rad = ls_conventional_radiometry(params);
  if (s.shape == TargetShape::Step && !s.has("target.step_y_m")) {
    s.notes.push_back(
        fmt::format("{}: a step with a column edge is rasterised into a depth map for ls-conventional", s.file));
    s = rasterised(s, rad);
  }
  if (s.shape == TargetShape::Objects) s = rasterised(s, rad);
  if (s.light.present) {
    const NativeLight n = native_light(s, rad, &s.notes);
    if (s.has("beam.power_W") || s.has("background.irradiance_W_per_m2"))
      s.notes.push_back(
          fmt::format("{}: beam.power_W / background.irradiance_W_per_m2 override [source] / [ambient] "
                      "for ls-conventional",
                      s.file));
    if (!s.has("beam.power_W")) s.beam_power_W = s.light.source_power_W;
    if (!s.has("background.irradiance_W_per_m2")) s.background_irradiance_W_per_m2 = n.ambient_in_band_W_per_m2;
    if (!s.has("beam.reference_distance_m")) s.reference_distance_m = s.distance_m;
  }
  return s;
}

SceneOptics::SceneOptics(const LsConventionalConfig& config, const Scene& scene) : config_(config), scene_(scene) {
  const PixelConfig& px = config.pixel;
  const double f = config.optics.focal_length_m;
  // The camera's radiometry: the preset's, unless the scene's [camera] overrides it.
  const double f_number = scene.has("camera.f_number") ? scene.f_number : config.optics.f_number;
  const double fill_factor = scene.has("camera.fill_factor") ? scene.fill_factor : px.fill_factor;
  const double responsivity =
      scene.has("camera.responsivity_A_per_W") ? scene.responsivity_A_per_W : px.responsivity_A_per_W;
  const double lens_area = kPi * std::pow(f / (2 * f_number), 2);
  const double sigma_px = golden::spot_sigma_px(config.spot);
  // rho (P / rows) A_lens / pi -> current at the spot peak -> swing; divided by z^2 later.
  const double collected_z2 = scene.reflectance * (scene.beam_power_W / px.rows) * lens_area / kPi;
  const double peak_current_z2 = responsivity * fill_factor * collected_z2 / (sigma_px * std::sqrt(2 * kPi));
  signal_per_inv_z2_V_ = golden::voltage_from_current_V(peak_current_z2, px.integration_time_s, px.pd_capacitance_F);
  const double bg_current = responsivity * fill_factor * px.pitch_m * px.pitch_m * scene.reflectance *
                            scene.background_irradiance_W_per_m2 / (4 * f_number * f_number);
  background_V_ = golden::voltage_from_current_V(bg_current, px.integration_time_s, px.pd_capacitance_F);
  if (scene.shape == TargetShape::DepthMap) depth_grid_m_ = scene.depth_map->resample(px.rows, px.columns);
  if (config.fixed_pattern.any())
    pattern_ =
        std::make_shared<const systemc::PixelPattern>(systemc::make_pixel_pattern(config, config.fixed_pattern.seed));
  taps_ = systemc::ls_conventional_blur_taps(config);
  // The beam must actually sweep: every position must leave the projector in front (0 < a_p < pi)
  // — always true for cot finite — and not run parallel to a tilted target.
  cot_.resize(static_cast<std::size_t>(beam_positions()));
  for (int b = 0; b < beam_positions(); ++b) {
    const double c = cot_[static_cast<std::size_t>(b)] = beam_cot(b);
    if (!std::isfinite(c))
      throw UserError(fmt::format("{}: beam.reference_distance_m = {:g} gives a degenerate beam angle at position {}",
                                  scene.file, scene.reference_distance_m, b));
  }
}

double SceneOptics::beam_cot(int b) const {
  const double f = config_.optics.focal_length_m, d = config_.optics.baseline_m, p = config_.pixel.pitch_m;
  const double u = static_cast<double>(b) * columns() / beam_positions() + scene_.column_offset_px;
  const double x_e = (u - principal_column_px()) * p;
  return (f * d / scene_.reference_distance_m - x_e) / f;  // x_e = f d / l_ref - f cot(a_p)
}

double SceneOptics::beam_angle_rad(int b) const { return std::atan2(1.0, cot_beam(b)); }

RowTruth SceneOptics::truth(int b, int row) const { return truth(b, cot_beam(b), row); }

RowTruth SceneOptics::truth(int b, double cot, int row) const {
  const double f = config_.optics.focal_length_m, d = config_.optics.baseline_m, p = config_.pixel.pitch_m;
  const double y_e = (row - principal_row_px()) * p;
  double z = 0;
  switch (scene_.shape) {
    case TargetShape::Plane: z = scene_.distance_m; break;
    case TargetShape::Tilted: {
      // z = l0 + x tx + y ty with x = d/2 - z cot, y = z y_e / f.
      const double tx = std::tan(scene_.tilt_x_rad), ty = std::tan(scene_.tilt_y_rad);
      const double den = 1 + tx * cot - ty * y_e / f;
      z = den > 0 ? (scene_.distance_m + 0.5 * d * tx) / den : -1;
      break;
    }
    case TargetShape::Step:
      z = scene_.near_distance_m * y_e / f > scene_.step_y_m ? scene_.near_distance_m : scene_.distance_m;
      break;
    case TargetShape::DepthMap: z = depth_map_z(b, row); break;
    case TargetShape::Objects: z = -1; break;  // rasterised into a depth map by ls_conventional_scene
  }
  RowTruth t;
  t.background_V = background_V_;
  if (!(z > 0) || !std::isfinite(z)) return t;  // the beam misses the target in front of the sensor
  t.hit = true;
  t.range_m = z;
  const double x_e = f * d / z - f * cot;
  t.centre_px = x_e / p + principal_column_px();
  t.visible = t.centre_px >= 0 && t.centre_px <= columns() - 1;
  t.signal_V = signal_per_inv_z2_V_ / (z * z);
  return t;
}

double SceneOptics::depth_map_z(int b, int row) const {
  // The lit point is where the row's depth profile meets the beam (scene/depth_map.h).
  const double f = config_.optics.focal_length_m, d = config_.optics.baseline_m, p = config_.pixel.pitch_m;
  const double cot = cot_beam(b);
  const int n = columns();
  const double* z = depth_grid_m_.data() + static_cast<std::size_t>(row) * n;
  auto g = [&](double c) { return c - ((f * d / row_depth_m(z, n, c) - f * cot) / p + principal_column_px()); };
  const double c = first_lit_column(n, g);
  return c < 0 ? -1 : row_depth_m(z, n, c);
}

void SceneOptics::stimulus(std::uint64_t frame, systemc::FrameStimulus& out) const {
  const int b = beam_position(frame);
  const double cot = cot_beam(b);
  out.rows.resize(static_cast<std::size_t>(rows()));
  out.pattern = pattern_.get();
  const bool spread = !taps_.empty();
  const int first = spread ? 0 : std::clamp(out.first_row, 0, rows());
  const int last = spread || out.row_count < 0 ? rows() : std::min(rows(), first + out.row_count);
  const auto illumination = [](const RowTruth& t) {
    return systemc::RowIllumination{t.hit ? t.signal_V : 0.0, t.background_V, t.hit ? t.centre_px : 0.0};
  };
  if (scene_.shape == TargetShape::Plane && last > first) {
    // A plane puts the same lit point on every row: one truth for the frame access, its row copied
    // to the others in doubling blocks (memcpy's wide stores; one row at a time was three 8-byte
    // stores a row, 6% of the map).
    systemc::RowIllumination* p = out.rows.data() + first;
    const std::size_t n = static_cast<std::size_t>(last - first);
    p[0] = illumination(truth(b, cot, first));
    for (std::size_t have = 1; have < n; have *= 2) std::memcpy(p + have, p, std::min(have, n - have) * sizeof *p);
  } else {
    for (int r = first; r < last; ++r) out.rows[static_cast<std::size_t>(r)] = illumination(truth(b, cot, r));
  }
  if (spread) systemc::spread_spot(config_, taps_, out);
}

double SceneOptics::range_from_centre_m(int b, double centre_px) const {
  const double f = config_.optics.focal_length_m, d = config_.optics.baseline_m;
  const double x_e = (centre_px - principal_column_px()) * config_.pixel.pitch_m;
  return d * f / (x_e + f * cot_beam(b));
}

}  // namespace rangesim::scene
