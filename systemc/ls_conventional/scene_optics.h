#pragma once
// ls-conventional's scene adapter (beside the sensor; scene/ is only the reader).
// Optics of a scene: from the target and the sheet beam to the per-row stimulus of the pixel
// array (spot-peak and background swings at the end of integration, V = I t / C, and the spot
// centre), and the exact ground truth of every (beam position, row).
//
// Geometry (golden/common/triangulation.h, in 3-D): camera lens at x = -d/2, projector at x = +d/2, both
// at y = 0 looking along z (depth). Image coordinates x_e = (column - c_x) pitch and
// y_e = (row - c_y) pitch with the principal point at the array centre c = (n - 1) / 2. A pixel
// row sees the points with y = z y_e / f. The beam of position b is the vertical plane
// x = d/2 - z cot(a_p); its image column follows from x_e = f (x + d/2) / z, i.e.
//   x_e = f d / z - f cot(a_p)           (the inverse of range = d f / (x_e + f cot a_p), which
//                                         is golden::range_from_image_m written without tangents)
// Beam angles: a_p(b) puts the stripe at column u_b = b columns / beam_positions + column_offset_px
// on a plane at reference_distance_m. Target depth z along a row: plane z = distance; tilted
// z = distance + x tan(tilt_x) + y tan(tilt_y), solved with the beam plane and the row's ray;
// step: the near face (z = near_distance_m) where the row sees y > step_y_m there, else the wall;
// depth_map: the image resampled to the pixel grid gives the depth seen by each pixel, and the
// lit point of a row is the first column (from the left) where the stripe of that depth lands on
// that column (a bisection on the bilinear depth profile).
//
// Radiometry (Lambertian target, on-axis lens, no vignetting, no lens losses):
//   sheet power per row           P / rows (the sheet spans the array's rows)
//   power collected by the lens   rho (P / rows) A_lens / (pi z^2),  A_lens = pi (f / 2 F#)^2
//   spot-peak photocurrent        R ff collected / (sigma_px sqrt(2 pi))   (Gaussian across the row)
//   background photocurrent       R ff pitch^2 rho E_bg / (4 F#^2)        (camera equation)
// and V = I t_int / C_pd (thesis eq. 3.1).
#include <cstdint>
#include <memory>
#include <vector>

#include "core/ls_conventional/config.h"
#include "scene/scene.h"
#include "systemc/common/optical_blur.h"
#include "systemc/ls_conventional/frame_stimulus.h"

namespace rangesim::scene {

// What the beam of one position really does on one row.
struct RowTruth {
  bool hit = false;         // the beam meets the target in front of the sensor on this row
  bool visible = false;     // ... and its stripe centre lies on the array, 0 <= centre_px <= columns - 1
  double centre_px = 0;     // exact image column of the stripe centre
  double range_m = 0;       // depth z of the lit point
  double signal_V = 0;      // spot-peak swing at the end of integration
  double background_V = 0;  // background swing at the end of integration
};

// The scene as ls-conventional takes it: a physical scene's light ([ambient], [source]) as the
// beam power and in-band background irradiance SceneOptics reads (unless the file sets the
// sensor's own beam.power_W / background.irradiance_W_per_m2), the beam aimed at the target's
// distance unless beam.reference_distance_m says otherwise, and a step given by a column edge
// (the time-of-flight scenes' form) rasterised into a depth map. Notes go to Scene::notes.
Scene ls_conventional_scene(Scene s, const ParamSet& params);

class SceneOptics {
 public:
  // Throws UserError (naming the scene file and keys) when the geometry cannot work, e.g. a beam
  // position parallel to the target or a reference distance the beam cannot scan.
  SceneOptics(const LsConventionalConfig& config, const Scene& scene);

  int beam_positions() const { return config_.timing.beam_positions; }
  int rows() const { return config_.pixel.rows; }
  int columns() const { return config_.pixel.columns; }
  // Beam position of a frame access: frames cycle through the positions.
  int beam_position(std::uint64_t frame) const { return static_cast<int>(frame % beam_positions()); }
  double beam_angle_rad(int b) const;  // a_p in (0, pi)
  double principal_column_px() const { return 0.5 * (columns() - 1); }
  double principal_row_px() const { return 0.5 * (rows() - 1); }

  RowTruth truth(int b, int row) const;
  // The pixel array's stimulus of frame access `frame` (systemc::StimulusSource), with the chip's
  // fixed pattern (fixed_pattern.*, made once here) and the spot spread by blur.* when they are on
  // (systemc/ls_conventional/nonideal_pattern.h); with blur every row is filled (the spread
  // crosses rows), the spread swings only for the band's.
  void stimulus(std::uint64_t frame, systemc::FrameStimulus& out) const;
  // Depth from an estimated stripe column on a row at beam position b (triangulation).
  double range_from_centre_m(int b, double centre_px) const;

 private:
  // cot(a_p) of beam position b, made once per position: truth(), stimulus() and
  // range_from_centre_m() ask for it at every row of every frame access.
  double cot_beam(int b) const { return cot_[static_cast<std::size_t>(b)]; }
  double beam_cot(int b) const;                           // what cot_beam(b) holds
  RowTruth truth(int b, double cot_beam, int row) const;  // truth(b, row) with cot_beam(b) made once
  double depth_map_z(int b, int row) const;               // depth_map: depth of the lit point on a row (< 0: none)

  LsConventionalConfig config_;
  Scene scene_;
  double signal_per_inv_z2_V_ = 0;                        // spot-peak swing times z^2 (V m^2) at reflectance rho
  double background_V_ = 0;                               // background swing
  std::vector<double> cot_;                               // cot_beam(b) of every beam position
  std::vector<double> depth_grid_m_;                      // depth_map: the map resampled to the pixel grid, row-major
  std::shared_ptr<const systemc::PixelPattern> pattern_;  // the chip's fixed pattern (null: off)
  std::vector<systemc::BlurTap> taps_;                    // the spread (empty: none)
};

}  // namespace rangesim::scene
