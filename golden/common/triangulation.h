#pragma once
// Light-section triangulation (thesis eq. 1.1-1.8).
//
// Geometry in the x-z plane: camera lens at x = -d/2, sheet-beam projector at x = +d/2, target
// p = (x_p, l) with l its distance from the baseline. The camera sees p at angle a_i to the x-axis,
// tan a_i = f / x_e (eq. 1.1, x_e the image position on the focal plane); the beam leaves at a_p.
// Then tan a_i = l / (d/2 + x_p) and tan a_p = l / (d/2 - x_p) (eq. 1.3-1.4, which the thesis
// prints without the tan). Adding the two baselines, d = l / tan a_i + l / tan a_p, so
//   l   = d tan a_p tan a_i / (tan a_p + tan a_i)
//   x_p = d (tan a_p - tan a_i) / (2 (tan a_p + tan a_i))          (eq. 1.5, as printed)
// The thesis's eq. 1.6-1.8 carry a spurious factor 1/2 on l (and so on y_p, z_p); we use the
// derived form. Out of the x-z plane, tan theta = f / y_e (eq. 1.2), y_p = l sin theta,
// z_p = l cos theta (eq. 1.7-1.8 without the 1/2).
//
// Range accuracy: an image-position error dx_e maps to a range error |dl/dx_e| dx_e. At the
// reference target x_p = 0 at distance l, tan a_p = tan a_i = 2 l / d and |dl/dx_e| = l^2 / (f d),
// so one pixel of image position is l^2 pitch / (f d) metres of range.
#include "core/ls_conventional/config.h"

namespace rangesim::golden {

struct TriangulatedPoint {
  double x_m = 0;      // x_p along the baseline, 0 midway between lens and projector
  double range_m = 0;  // l: distance from the baseline
  double y_m = 0;      // y_p = l sin theta
  double z_m = 0;      // z_p = l cos theta
};

// From the tangents of the two angles (eq. 1.5 and the corrected 1.6).
double range_from_tangents_m(double tan_beam, double tan_image, double baseline_m);
double x_from_tangents_m(double tan_beam, double tan_image, double baseline_m);

// From the image position x_e (and y_e) on the focal plane and the beam angle a_p (radians).
TriangulatedPoint triangulate(const OpticsConfig& optics, double image_x_m, double image_y_m, double beam_angle_rad);
double range_from_image_m(const OpticsConfig& optics, double image_x_m, double beam_angle_rad);

// Image position x_e and beam angle a_p that see the reference target x_p = 0 at distance l.
double reference_image_x_m(const OpticsConfig& optics, double distance_m);
double reference_beam_angle_rad(const OpticsConfig& optics, double distance_m);

// Range change per pixel of image position at the reference target: l^2 pitch / (f d).
double range_per_px_m(const OpticsConfig& optics, double pitch_m, double distance_m);

}  // namespace rangesim::golden
