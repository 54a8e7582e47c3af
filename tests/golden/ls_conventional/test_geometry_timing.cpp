// Triangulation (eq. 1.1-1.8, with the 1/2 of eq. 1.6-1.8 removed) and the frame timing.
#include <gtest/gtest.h>

#include <cmath>

#include "golden/ls_conventional/frame_timing.h"
#include "golden/common/triangulation.h"
#include "test_helpers.h"

namespace rangesim::golden {
namespace {

TEST(GoldenTriangulation, HandValues) {
  // Symmetric target: tan a_p = tan a_i = 2 -> l = d * 4 / 4 = d, x_p = 0 (eq. 1.6 would give d/2).
  EXPECT_DOUBLE_EQ(range_from_tangents_m(2, 2, 0.1), 0.1);
  EXPECT_DOUBLE_EQ(x_from_tangents_m(2, 2, 0.1), 0.0);
  // Target at (x_p, l) = (0.02, 0.5) with d = 0.1: tan a_i = l / (d/2 + x_p), tan a_p = l / (d/2 - x_p).
  const double ti = 0.5 / 0.07, tp = 0.5 / 0.03;
  EXPECT_NEAR(range_from_tangents_m(tp, ti, 0.1), 0.5, 1e-15);
  EXPECT_NEAR(x_from_tangents_m(tp, ti, 0.1), 0.02, 1e-15);
}

TEST(GoldenTriangulation, ReferenceTargetAndOutOfPlane) {
  const LsConventionalConfig cfg = test::preset_config();
  const double l = cfg.optics.distance_m;
  const double xe = reference_image_x_m(cfg.optics, l), ap = reference_beam_angle_rad(cfg.optics, l);
  EXPECT_NEAR(range_from_image_m(cfg.optics, xe, ap), l, 1e-12);
  // y_e = 0: theta = 90 deg (tan theta = f / y_e) puts the whole range on y (eq. 1.7-1.8 as written).
  const TriangulatedPoint p = triangulate(cfg.optics, xe, 1e-3, ap);
  const double theta = std::atan2(cfg.optics.focal_length_m, 1e-3);
  EXPECT_NEAR(p.range_m, l, 1e-12);
  EXPECT_NEAR(p.y_m, l * std::sin(theta), 1e-12);
  EXPECT_NEAR(p.z_m, l * std::cos(theta), 1e-12);
  EXPECT_NEAR(p.x_m, 0, 1e-15);
}

TEST(GoldenTriangulation, RangePerPixelMatchesNumericalDerivative) {
  const LsConventionalConfig cfg = test::preset_config();
  for (double l : {0.6, 1.1, 2.0}) {
    const double xe = reference_image_x_m(cfg.optics, l), ap = reference_beam_angle_rad(cfg.optics, l);
    const double dx = 1e-9;
    const double deriv =
        (range_from_image_m(cfg.optics, xe + dx, ap) - range_from_image_m(cfg.optics, xe - dx, ap)) / (2 * dx);
    const double analytic = range_per_px_m(cfg.optics, cfg.pixel.pitch_m, l);
    EXPECT_NEAR(std::fabs(deriv) * cfg.pixel.pitch_m, analytic, 1e-6 * analytic) << l;
    EXPECT_NEAR(analytic, l * l * cfg.pixel.pitch_m / (cfg.optics.focal_length_m * cfg.optics.baseline_m), 1e-15);
  }
  // Published: 0.2 sub-pixel = 1.10 mm at 600 mm (the preset's baseline is calibrated to it).
  EXPECT_NEAR(0.2 * range_per_px_m(cfg.optics, cfg.pixel.pitch_m, 0.6), 1.10e-3, 0.005e-3);
}

TEST(GoldenFrameTiming, PresetGivesPublishedRates) {
  const LsConventionalConfig cfg = test::preset_config();
  const FrameTiming t = frame_timing(cfg.timing, 4);
  // 4 + 4 (1 + 2 + 2 * 9) + 12 = 100 cycles at 39.45 MHz.
  EXPECT_EQ(t.frame_cycles, 100);
  EXPECT_NEAR(t.frame_access_rate_Hz, 394.5e3, 1e-6);  // published
  EXPECT_NEAR(t.range_maps_per_s, 1052.0, 1e-9);       // published
  EXPECT_NEAR(t.frame_time_s, 100 / 39.45e6, 1e-18);
  EXPECT_NEAR(t.range_map_time_s, 375 * 100 / 39.45e6, 1e-15);
  ASSERT_EQ(t.phases.size(), 5u);
  const char* names[] = {"reset", "latch", "search", "address_stream", "output"};
  const long long cycles[] = {4, 4, 8, 72, 12};
  long long sum = 0;
  for (int i = 0; i < 5; ++i) {
    EXPECT_EQ(t.phases[i].name, names[i]);
    EXPECT_EQ(t.phases[i].cycles, cycles[i]);
    EXPECT_NEAR(t.phases[i].time_s, cycles[i] / 39.45e6, 1e-18);
    sum += t.phases[i].cycles;
  }
  EXPECT_EQ(sum, t.frame_cycles);
  EXPECT_EQ(frame_timing(cfg.timing, 1).frame_cycles, 4 + 21 + 12);
}

}  // namespace
}  // namespace rangesim::golden
