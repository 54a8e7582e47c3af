// Scenes and their optics (plain C++): validation messages, the ground truth against the golden
// triangulation, radiometry, and a noise-free kernel run reproducing the truth to quantisation.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>
#include <unistd.h>

#include "core/preset.h"
#include "core/user_error.h"
#include "golden/ls_conventional/multisampling.h"
#include "golden/common/row_model.h"
#include "golden/common/triangulation.h"
#include "systemc/ls_conventional/scene_optics.h"
#include "scene/scene.h"
#include "systemc/ls_conventional/pixel_array_kernel.h"
#include "systemc/ls_conventional/sensor.h"

namespace sc = rangesim::scene;
using rangesim::LsConventionalConfig;

namespace {

const std::string kScenes = RANGESIM_SCENE_DIR;

LsConventionalConfig preset() {
  return rangesim::ls_conventional_from_params(rangesim::load_preset("ls-conventional"));
}

std::string write_temp(const std::string& text) {
  static int n = 0;
  const auto p = std::filesystem::temp_directory_path() /
                 ("rangesim-scene-" + std::to_string(::getpid()) + "-" + std::to_string(n++) + ".toml");
  std::ofstream(p) << text;
  return p.string();
}

std::string error_of(const std::string& text) {
  try {
    sc::load_scene(write_temp(text), "ls-conventional");
  } catch (const rangesim::UserError& e) {
    return e.what();
  }
  return "";
}

const char* kGood = R"(
[scene]
name = "t"
[target]
shape = "plane"
distance_m = 1.0
reflectance = 0.5
[beam]
power_W = 0.5
reference_distance_m = 1.1
[background]
irradiance_W_per_m2 = 5.0
[camera]
f_number = 1.4
fill_factor = 0.5
responsivity_A_per_W = 0.4
)";

std::string replace(std::string s, const std::string& from, const std::string& to) {
  const auto i = s.find(from);
  EXPECT_NE(i, std::string::npos) << from;
  return s.replace(i, from.size(), to);
}

}  // namespace

TEST(Scene, ExampleScenesLoad) {
  for (const char* name : {"plane", "tilted", "step"}) {
    const sc::Scene s = sc::load_scene(kScenes + "/" + name + ".toml", "ls-conventional");
    EXPECT_EQ(s.name, name);
  }
  EXPECT_EQ(error_of(kGood), "");
}

TEST(Scene, BadInputNamesFileKeyAndRange) {
  std::string e = error_of(replace(kGood, "reflectance = 0.5", "reflectance = 1.5"));
  EXPECT_NE(e.find("target.reflectance = 1.5 is out of range; allowed: (0, 1]"), std::string::npos) << e;
  EXPECT_NE(e.find(".toml:7"), std::string::npos) << e;  // file and line
  e = error_of(replace(kGood, "reflectance = 0.5", "reflectance = 0.5\ncolour = 3"));
  EXPECT_NE(e.find("unknown key 'target.colour'"), std::string::npos) << e;
  e = error_of(replace(kGood, "beam]\npower_W = 0.5\n", "beam]\n"));
  EXPECT_NE(e.find("missing key 'beam.power_W'"), std::string::npos) << e;
  e = error_of(replace(kGood, "\"plane\"", "\"sphere\""));
  EXPECT_NE(e.find("allowed: plane, tilted, step"), std::string::npos) << e;
  e = error_of(replace(kGood, "distance_m = 1.0", "distance_m = \"far\""));
  EXPECT_NE(e.find("target.distance_m must be a number"), std::string::npos) << e;
  e = error_of(replace(kGood, "\"plane\"", "\"tilted\""));
  EXPECT_NE(e.find("missing key 'target.tilt_x_rad'"), std::string::npos) << e;
  e = error_of(replace(kGood, "\"plane\"", "\"step\"\nnear_distance_m = 1.5\nstep_y_m = 0"));
  EXPECT_NE(e.find("must be < target.distance_m"), std::string::npos) << e;
  e = error_of("[scene\nname=");
  EXPECT_NE(e.find("TOML syntax error"), std::string::npos) << e;
  EXPECT_THROW(sc::load_scene("/nonexistent/scene.toml", "ls-conventional"), rangesim::UserError);
}

TEST(SceneOptics, GroundTruthAgreesWithGoldenTriangulation) {
  const LsConventionalConfig c = preset();
  for (const char* name : {"plane", "tilted", "step"}) {
    const sc::Scene s = sc::load_scene(kScenes + "/" + name + ".toml", "ls-conventional");
    const sc::SceneOptics o(c, s);
    int visible = 0;
    for (int b = 0; b < o.beam_positions(); b += 17)
      for (int r = 0; r < o.rows(); r += 13) {
        const sc::RowTruth t = o.truth(b, r);
        if (!t.hit) continue;
        visible += t.visible;
        const double x_e = (t.centre_px - o.principal_column_px()) * c.pixel.pitch_m;
        if (std::fabs(x_e) < 1e-9) continue;
        // golden: range from the image position and the beam angle (eq. 1.1-1.6 corrected).
        EXPECT_NEAR(rangesim::golden::range_from_image_m(c.optics, x_e, o.beam_angle_rad(b)), t.range_m,
                    1e-9 * t.range_m)
            << name << " b " << b << " r " << r;
        EXPECT_NEAR(o.range_from_centre_m(b, t.centre_px), t.range_m, 1e-12 * t.range_m);
      }
    EXPECT_GT(visible, 100) << name;
  }
}

TEST(SceneOptics, PlaneAtTheReferenceDistancePutsTheStripeOnItsColumn) {
  const LsConventionalConfig c = preset();
  sc::Scene s = sc::load_scene(kScenes + "/plane.toml", "ls-conventional");
  s.distance_m = s.reference_distance_m;
  const sc::SceneOptics o(c, s);
  for (int b : {0, 100, 374}) EXPECT_NEAR(o.truth(b, 50).centre_px, b + s.column_offset_px, 1e-9);
  // Radiometry: signal falls as 1/z^2, background does not depend on z.
  sc::Scene far = s;
  far.distance_m = 2 * s.distance_m;
  const sc::SceneOptics of(c, far);
  EXPECT_NEAR(of.truth(10, 0).signal_V * 4, o.truth(10, 0).signal_V, 1e-12);
  EXPECT_EQ(of.truth(10, 0).background_V, o.truth(10, 0).background_V);
  // The example plane: about 0.68 V over 0.010 V at 1.0 m (docs/simulate.md).
  const sc::SceneOptics ex(c, sc::load_scene(kScenes + "/plane.toml", "ls-conventional"));
  EXPECT_NEAR(ex.truth(100, 0).signal_V, 0.684, 0.01);
  EXPECT_NEAR(ex.truth(100, 0).background_V, 0.0101, 0.0005);
}

TEST(SceneOptics, NoiseFreeKernelRunEqualsGoldenEstimateOfTheScene) {
  // The whole chain scene -> optics -> kernels -> centre, noise-free: every row's centre equals
  // golden::noise_free_estimate at the scene's operating point, and the rms error is the
  // quantisation error only (well under a pixel).
  const LsConventionalConfig c = preset();
  const sc::SceneOptics o(c, sc::load_scene(kScenes + "/tilted.toml", "ls-conventional"));
  rangesim::systemc::SensorKernelOptions k;
  k.pixel.noise = rangesim::systemc::PixelNoiseConfig::none();
  rangesim::systemc::SensorRunOptions run;
  run.frames = 12;
  const auto res = rangesim::systemc::run_sensor_kernel(
      c, k, [&o](std::uint64_t f, rangesim::systemc::FrameStimulus& s) { o.stimulus(f, s); }, run);
  double sq = 0;
  int n = 0;
  for (const auto& fr : res.frames)
    for (int r = 0; r < o.rows(); ++r) {
      const sc::RowTruth t = o.truth(o.beam_position(fr.frame), r);
      const auto& p = fr.rows[static_cast<std::size_t>(r)];
      const auto g = rangesim::golden::noise_free_estimate(
          rangesim::golden::make_row_model(c, t.signal_V, t.background_V), t.centre_px);
      ASSERT_EQ(p.valid, t.hit && g.detected) << r;
      if (!p.valid) continue;
      ASSERT_EQ(p.exact_centre_px(), g.centre_px);
      if (t.visible) {
        sq += std::pow(p.centre_px() - t.centre_px, 2);
        ++n;
      }
    }
  ASSERT_GT(n, 1000);
  EXPECT_LT(std::sqrt(sq / n), 0.2);
}

// The point spread across rows (blur.*, systemc/ls_conventional/nonideal_pattern.h): at the step
// (0.9 m over 1.2 m, by row) a noise-free row near the edge sees both stripes and its centre gives a
// range of neither surface (a mixed pixel); without the spread every row gives one surface's range.
TEST(SceneOptics, BlurMakesMixedRowsAtTheStep) {
  for (bool blur : {false, true}) {
    LsConventionalConfig c = preset();
    if (blur) c.blur.psf = rangesim::PsfKind::Gaussian, c.blur.gaussian_sigma_px = 1.0;
    const sc::Scene s = sc::load_scene(kScenes + "/step.toml", "ls-conventional");
    const sc::SceneOptics o(c, s);
    const int b = o.beam_positions() / 2;
    rangesim::systemc::PixelArrayOptions opt;
    opt.noise = rangesim::systemc::PixelNoiseConfig::none();
    rangesim::systemc::PixelArrayKernel px(
        c, opt, [&o](std::uint64_t f, rangesim::systemc::FrameStimulus& st) { o.stimulus(f, st); });
    px.reset_frame(static_cast<std::uint64_t>(b));
    for (int k = 1; k <= c.multisampling.samplings; ++k) px.sample(k);
    EXPECT_EQ(px.per_pixel(), blur);
    int mixed = 0, rows = 0;
    for (int r = 0; r < o.rows(); ++r) {
      const rangesim::systemc::ActivationRow& a = px.row(r);
      int left = -1, right = -1;
      for (int i = 0; i < o.columns(); ++i)
        if (a.test(i)) right = i, left = left < 0 ? i : left;
      if (left < 0) continue;
      ++rows;
      const double z = o.range_from_centre_m(b, 0.5 * (left + right));
      mixed += z > 0.92 && z < 1.18;
    }
    EXPECT_GT(rows, 300);
    if (blur)
      EXPECT_GE(mixed, 2);
    else
      EXPECT_EQ(mixed, 0);
  }
}
