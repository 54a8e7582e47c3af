// The tof-lockin scene reader: the example scenes load; bad input names file,
// key and range.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>

#include "core/user_error.h"
#include "lockin_sc_test_util.h"
#include "scene/scene.h"
#include "systemc/tof_lockin/scene_adapter.h"
#include "systemc/tof_lockin/lockin_scene.h"

namespace rangesim::systemc::lockin {
namespace {

// The tof-lockin scenes go through the one scene reader (scene/scene.h).
LockinScene load_lockin_scene(const std::string& path) {
  return scene::to_lockin_scene(scene::load_scene(path, "tof-lockin"), test::edited_config({}));
}

std::string write_scene(const std::string& text) {
  const std::string path = ::testing::TempDir() + "lockin_scene_test.toml";
  std::ofstream(path) << text;
  return path;
}

void expect_error(const std::string& text, const std::vector<std::string>& parts) {
  const std::string path = write_scene(text);
  try {
    load_lockin_scene(path);
    ADD_FAILURE() << "no error for:\n" << text;
  } catch (const rangesim::UserError& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find(path), std::string::npos) << msg;
    for (const auto& p : parts) EXPECT_NE(msg.find(p), std::string::npos) << "'" << p << "' not in: " << msg;
  }
  std::remove(path.c_str());
}

TEST(LockinScene, ExamplesLoad) {
  const LockinScene p = load_lockin_scene(std::string(RANGESIM_SOURCE_DIR) + "/scenes/tof-lockin-plane.toml");
  EXPECT_EQ(p.shape, LockinScene::Shape::Plane);
  EXPECT_DOUBLE_EQ(p.distance_m, 3.0);
  const LockinScene s = load_lockin_scene(std::string(RANGESIM_SOURCE_DIR) + "/scenes/tof-lockin-step.toml");
  EXPECT_EQ(s.shape, LockinScene::Shape::Step);
  EXPECT_DOUBLE_EQ(s.distance_at(0, 0, 100), 2.0);
  EXPECT_DOUBLE_EQ(s.distance_at(0, 99, 100), 9.0);
  const TofLockinConfig cfg = test::edited_config({});
  const auto st = s.stimulus(cfg);
  ASSERT_EQ(st.size(), static_cast<std::size_t>(cfg.pixel.rows) * cfg.pixel.columns);
  EXPECT_NEAR(st[0].signal_A, 1.2e-9, 1e-21);
  EXPECT_NEAR(st.back().signal_A, 1.2e-9 * 4.0 / 81.0, 1e-21);
}

const char* kGood =
    "[scene]\nname = \"x\"\n[target]\nshape = \"plane\"\ndistance_m = "
    "2.0\n[light]\nsignal_photocurrent_A = 1e-9\n";

TEST(LockinScene, BadInputNamesFileKeyAndRange) {
  EXPECT_NO_THROW(load_lockin_scene(write_scene(kGood)));
  expect_error(
      "[scene]\nname = \"x\"\n[target]\ndistance_m = "
      "-1.0\n[light]\nsignal_photocurrent_A = 1e-9\n",
      {"target.distance_m", "allowed", "1000"});
  expect_error(
      "[scene]\nname = \"x\"\n[target]\ndistance_m = "
      "1.0\n[light]\nsignal_photocurrent_A = 1e-9\nsignal_A = 2\n",
      {"unknown key 'light.signal_A'"});
  expect_error(
      "[scene]\nname = \"x\"\n[target]\nshape = \"cube\"\ndistance_m "
      "= 1.0\n[light]\nsignal_photocurrent_A = 1e-9\n",
      {"target.shape", "allowed: plane, step, depth_map"});
  expect_error("[scene]\nname = \"x\"\n[target]\ndistance_m = 1.0\n", {"light.signal_photocurrent_A", "missing"});
  expect_error(
      "[scene]\nname = \"x\"\n[target]\nshape = \"step\"\ndistance_m "
      "= 1.0\n[light]\nsignal_photocurrent_A = 1e-9\n",
      {"target.near_distance_m", "missing"});
  expect_error(
      "[scene]\nname = \"x\"\n[target]\ndistance_m = "
      "1.0\n[light]\nsignal_photocurrent_A = 1e-9\n[window]\nrows = 9999\n",
      {"window.rows", "[0, 4096]"});
  expect_error("[scene\nname = 1", {":1:"});
}

}  // namespace
}  // namespace rangesim::systemc::lockin
