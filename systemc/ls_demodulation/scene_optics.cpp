#include "systemc/ls_demodulation/scene_optics.h"

#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "core/user_error.h"
#include "scene/depth_map.h"
#include "scene/physical.h"
#include "scene/scene.h"
#include "systemc/ls_demodulation/nonideal_stimulus.h"

namespace rangesim::scene {

DemodScene load_demod_scene(const std::string& path, const LsDemodulationConfig& cfg, const ParamSet& params) {
  Scene in = load_scene(path, "ls-demodulation");
  const SensorRadiometry rad = ls_demodulation_radiometry(params);
  if (in.shape == TargetShape::Tilted || in.shape == TargetShape::Step || in.shape == TargetShape::Objects)
    in = rasterised(in, rad);
  DemodScene s;
  s.notes = in.notes;
  s.file = path;
  s.name = in.name;
  s.description = in.description;
  s.shape = shape_name(in.shape);
  s.distance_m = in.distance_m;
  if (in.shape != TargetShape::DepthMap && (s.distance_m < 0.05 || s.distance_m > 100))
    throw UserError(fmt::format("{}: target.distance_m = {:g}: allowed 0.05 <= value <= 100 m (ls-demodulation)", path,
                                s.distance_m));
  s.tilt_m_per_row = in.get("target.tilt_m_per_row", 0.0);
  s.signal_A = in.get("beam.signal_A", 0.0);
  s.first_column_px = in.get("beam.first_column_px", 0.0);
  if (s.first_column_px > cfg.pixel.columns - 1.0)
    throw UserError(fmt::format("{}: beam.first_column_px = {:g}: allowed -1000 <= value <= {} (pixel.columns - 1)",
                                path, s.first_column_px, cfg.pixel.columns - 1));
  s.columns_per_frame = in.get("beam.columns_per_frame", 1.0);
  s.background_A = in.get("background.photocurrent_A", 0.0);
  if (in.light.present) {
    const NativeLight n = native_light(in, rad, &s.notes);
    if (in.has("beam.signal_A") || in.has("background.photocurrent_A"))
      s.notes.push_back(
          fmt::format("{}: beam.signal_A / background.photocurrent_A override [ambient] / [source] for "
                      "ls-demodulation",
                      path));
    if (!in.has("beam.signal_A")) s.signal_A = n.signal_at(s.distance_m);
    if (!in.has("background.photocurrent_A")) s.background_A = n.background;
    // The first stripe near column 3 at the scene's distance, unless the file aims the beam.
    const DemodScene probe = s;
    const DemodOptics o{cfg, probe};
    if (!in.has("beam.first_column_px"))
      s.first_column_px = 3.0 - (o.disparity_px(s.distance_m) - o.disparity_px(cfg.optics.distance_m));
  }
  const double z_last = s.distance_m + s.tilt_m_per_row * (cfg.pixel.rows - 1);
  if (z_last < 0.05)
    throw UserError(
        fmt::format("{}: target.tilt_m_per_row = {:g} puts the last row at {:g} m; allowed: every row >= 0.05 m", path,
                    s.tilt_m_per_row, z_last));
  if (in.shape == TargetShape::DepthMap) {
    s.map_columns = cfg.pixel.columns;
    s.depth_map_m = in.depth_map->resample(cfg.pixel.rows, cfg.pixel.columns);
  }
  return s;
}

double DemodOptics::range_m(long long b, int row) const {
  if (sc.depth_map_m.empty()) return sc.distance_m + sc.tilt_m_per_row * row;
  const int n = cfg.pixel.columns;
  const double* z = sc.depth_map_m.data() + static_cast<std::size_t>(row) * sc.map_columns;
  auto g = [&](double c) {
    return c - (beam_column(b) + disparity_px(row_depth_m(z, n, c)) - disparity_px(cfg.optics.distance_m));
  };
  const double c = first_lit_column(n, g);
  return c < 0 ? -1 : row_depth_m(z, n, c);
}

double DemodOptics::centre_px(long long b, int row) const {
  const double z = range_m(b, row);
  return z > 0 ? beam_column(b) + disparity_px(z) - disparity_px(cfg.optics.distance_m) : NAN;  // NaN: the beam misses
}

bool DemodOptics::visible(long long b, int row) const {
  const double x = centre_px(b, row);
  return x >= 0 && x <= cfg.pixel.columns - 1;
}

double DemodOptics::range_from_centre_m(long long b, double x) const {
  const double d = x - beam_column(b) + disparity_px(cfg.optics.distance_m);
  return d > 0 ? cfg.optics.focal_length_m * cfg.optics.baseline_m / (cfg.pixel.pitch_m * d) : NAN;
}

void DemodOptics::stimulus(std::uint64_t f, systemc::DemodStimulus& s) const {
  const int R = cfg.pixel.rows, C = cfg.pixel.columns;
  const double sigma = cfg.spot.fwhm_px * cfg.spot.sigma_per_fwhm;
  s.beam_A.assign(static_cast<std::size_t>(R) * C, 0.0);
  s.background_A.assign(s.beam_A.size(), sc.background_A);
  for (int r = 0; r < R; ++r) {
    const double x0 = centre_px(static_cast<long long>(f), r);
    if (!std::isfinite(x0)) continue;  // no lit point on this row
    for (int c = 0; c < C; ++c)
      s.beam_A[static_cast<std::size_t>(r) * C + c] =
          sc.signal_A * std::exp(-(c - x0) * (c - x0) / (2 * sigma * sigma));
  }
  systemc::apply_demod_blur(cfg, s);           // the lens and the pixels' crosstalk
  systemc::apply_demod_fixed_pattern(cfg, s);  // the chip
}

}  // namespace rangesim::scene
