#include "golden/common/triangulation.h"

#include <cmath>

namespace rangesim::golden {

double range_from_tangents_m(double tan_beam, double tan_image, double baseline_m) {
  return baseline_m * tan_beam * tan_image / (tan_beam + tan_image);
}

double x_from_tangents_m(double tan_beam, double tan_image, double baseline_m) {
  return baseline_m * (tan_beam - tan_image) / (2 * (tan_beam + tan_image));
}

TriangulatedPoint triangulate(const OpticsConfig& optics, double image_x_m, double image_y_m, double beam_angle_rad) {
  const double tan_i = optics.focal_length_m / image_x_m;  // eq. 1.1
  const double tan_p = std::tan(beam_angle_rad);
  const double theta = std::atan2(optics.focal_length_m, image_y_m);  // eq. 1.2
  TriangulatedPoint p;
  p.x_m = x_from_tangents_m(tan_p, tan_i, optics.baseline_m);
  p.range_m = range_from_tangents_m(tan_p, tan_i, optics.baseline_m);
  p.y_m = p.range_m * std::sin(theta);
  p.z_m = p.range_m * std::cos(theta);
  return p;
}

double range_from_image_m(const OpticsConfig& optics, double image_x_m, double beam_angle_rad) {
  return range_from_tangents_m(std::tan(beam_angle_rad), optics.focal_length_m / image_x_m, optics.baseline_m);
}

double reference_image_x_m(const OpticsConfig& optics, double distance_m) {
  return optics.focal_length_m * optics.baseline_m / (2 * distance_m);  // f / tan a_i, tan a_i = 2 l / d
}

double reference_beam_angle_rad(const OpticsConfig& optics, double distance_m) {
  return std::atan(2 * distance_m / optics.baseline_m);
}

double range_per_px_m(const OpticsConfig& optics, double pitch_m, double distance_m) {
  return distance_m * distance_m * pitch_m / (optics.focal_length_m * optics.baseline_m);
}

}  // namespace rangesim::golden
