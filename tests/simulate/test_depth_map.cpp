// The one scene reader (scene/scene.h) and its depth maps (scene/depth_map.h): image formats,
// resampling, relative paths, per-sensor key sets, messages naming file, key and range; and the
// ls-conventional optics on a depth map against the same scene as a plane.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>
#include <unistd.h>

#include "core/ls_conventional/config.h"
#include "core/preset.h"
#include "core/user_error.h"
#include "scene/depth_map.h"
#include "systemc/ls_conventional/scene_optics.h"
#include "scene/scene.h"

namespace fs = std::filesystem;
namespace sc = rangesim::scene;

namespace {

const std::string kScenes = RANGESIM_SCENE_DIR;

fs::path temp_dir() {
  static int n = 0;
  const fs::path d =
      fs::temp_directory_path() / ("rangesim-depth-" + std::to_string(::getpid()) + "-" + std::to_string(n++));
  fs::create_directories(d);
  return d;
}

void write_bytes(const fs::path& p, const std::string& bytes) { std::ofstream(p, std::ios::binary) << bytes; }

std::string pfm(int w, int h, const std::vector<float>& top_down, bool little) {
  std::string s = "Pf\n" + std::to_string(w) + " " + std::to_string(h) + "\n" + (little ? "-1.0" : "1.0") + "\n";
  for (int y = h - 1; y >= 0; --y)  // PFM stores the bottom row first
    for (int x = 0; x < w; ++x) {
      std::uint32_t u;
      std::memcpy(&u, &top_down[static_cast<std::size_t>(y) * w + x], 4);
      for (int i = 0; i < 4; ++i) s += static_cast<char>(little ? (u >> (8 * i)) & 0xff : (u >> (8 * (3 - i))) & 0xff);
    }
  return s;
}

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const rangesim::UserError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST(DepthMap, ReadsAsciiAndBinaryPgmOf8And16BitsAndPfm) {
  const fs::path d = temp_dir();
  write_bytes(d / "a.pgm", "P2\n# comment\n2 2\n10\n0 5\n10 2\n");
  const sc::DepthMap a = sc::load_depth_map((d / "a.pgm").string(), "k", 1.0, 2.0, 0.01, 1e4);
  ASSERT_EQ(a.width, 2);
  EXPECT_DOUBLE_EQ(a.at(0, 0), 1.0);
  EXPECT_DOUBLE_EQ(a.at(1, 0), 1.5);
  EXPECT_DOUBLE_EQ(a.at(0, 1), 2.0);
  EXPECT_DOUBLE_EQ(a.at(1, 1), 1.2);
  write_bytes(d / "b.pgm", std::string("P5 3 1 255\n") + std::string("\x00\x80\xff", 3));
  const sc::DepthMap b = sc::load_depth_map((d / "b.pgm").string(), "k", 2.0, 1.0, 0.01, 1e4);  // near > far is allowed
  EXPECT_DOUBLE_EQ(b.at(0, 0), 2.0);
  EXPECT_DOUBLE_EQ(b.at(1, 0), 2.0 - 128.0 / 255.0);
  EXPECT_DOUBLE_EQ(b.at(2, 0), 1.0);
  write_bytes(d / "c.pgm", std::string("P5\n2 1\n65535\n") + std::string("\x01\x00\xff\xff", 4));  // big-endian
  const sc::DepthMap c = sc::load_depth_map((d / "c.pgm").string(), "k", 0.0 + 1.0, 3.0, 0.01, 1e4);
  EXPECT_DOUBLE_EQ(c.at(0, 0), 1.0 + 2.0 * 256.0 / 65535.0);
  EXPECT_DOUBLE_EQ(c.at(1, 0), 3.0);
  for (bool little : {true, false}) {
    write_bytes(d / "m.pfm", pfm(2, 2, {1.25f, 2.5f, 3.0f, 4.0f}, little));
    const sc::DepthMap m = sc::load_depth_map((d / "m.pfm").string(), "k", 0, 0, 0.01, 1e4);
    EXPECT_DOUBLE_EQ(m.at(0, 0), 1.25) << little;  // top-left, after the bottom-up flip
    EXPECT_DOUBLE_EQ(m.at(1, 0), 2.5);
    EXPECT_DOUBLE_EQ(m.at(0, 1), 3.0);
    EXPECT_DOUBLE_EQ(m.at(1, 1), 4.0);
  }
  fs::remove_all(d);
}

TEST(DepthMap, ResamplesBilinearlyToThePixelGrid) {
  sc::DepthMap m;
  m.width = 2, m.height = 1, m.depth_m = {1.0, 2.0};
  // 4 columns over 2 image pixels: centres at image x = -0.25, 0.25, 0.75, 1.25 (clamped at the edges).
  const auto r = m.resample(1, 4);
  EXPECT_DOUBLE_EQ(r[0], 1.0);
  EXPECT_DOUBLE_EQ(r[1], 1.25);
  EXPECT_DOUBLE_EQ(r[2], 1.75);
  EXPECT_DOUBLE_EQ(r[3], 2.0);
  const auto same = m.resample(1, 2);  // same size: the image itself
  EXPECT_DOUBLE_EQ(same[0], 1.0);
  EXPECT_DOUBLE_EQ(same[1], 2.0);
}

TEST(DepthMap, BadImagesNameFileKeyAndRange) {
  const fs::path d = temp_dir();
  const std::string key = "scene.toml:3: target.depth_map_file";
  auto load = [&](const std::string& name) { sc::load_depth_map((d / name).string(), key, 1, 2, 0.01, 100); };
  write_bytes(d / "x.png", "\x89PNG....");
  std::string e = error_of([&] { load("x.png"); });
  EXPECT_NE(e.find(key), std::string::npos) << e;
  EXPECT_NE(e.find("allowed PGM (P2, P5) or grayscale PFM (Pf)"), std::string::npos) << e;
  write_bytes(d / "t.pgm", "P5 4 4 255\n\x01\x02");
  e = error_of([&] { load("t.pgm"); });
  EXPECT_NE(e.find("raster too short"), std::string::npos) << e;
  EXPECT_NE(e.find((d / "t.pgm").string()), std::string::npos) << e;
  write_bytes(d / "g.pgm", "P2 2 1 10 3 11\n");
  e = error_of([&] { load("g.pgm"); });
  EXPECT_NE(e.find("gray level '11' at pixel 1; allowed an integer in [0, 10]"), std::string::npos) << e;
  write_bytes(d / "w.pgm", "P2 0 1 10\n");
  e = error_of([&] { load("w.pgm"); });
  EXPECT_NE(e.find("width = '0'; allowed an integer in [1, 16384]"), std::string::npos) << e;
  write_bytes(d / "r.pfm", pfm(1, 1, {500.0f}, true));
  e = error_of([&] { load("r.pfm"); });
  EXPECT_NE(e.find("distance 500 m at pixel (x 0, y 0) is out of range; allowed [0.01, 100] m"), std::string::npos)
      << e;
  e = error_of([&] { load("missing.pgm"); });
  EXPECT_NE(e.find("cannot read the depth-map image"), std::string::npos) << e;
  // A header alone must not allocate the raster it announces (16384^2 doubles = 2 GiB).
  write_bytes(d / "h.pgm", "P2 16384 16384 255\n0 1 2\n");
  e = error_of([&] { load("h.pgm"); });
  EXPECT_NE(e.find("raster too short for 16384 x 16384 pixels"), std::string::npos) << e;
  // Not a regular file: reading /dev/zero or a directory would never end or fail late.
  e = error_of([&] { sc::load_depth_map("/dev/zero", key, 1, 2, 0.01, 100); });
  EXPECT_NE(e.find("not a regular file"), std::string::npos) << e;
  e = error_of([&] { sc::load_depth_map(d.string(), key, 1, 2, 0.01, 100); });
  EXPECT_NE(e.find("not a regular file"), std::string::npos) << e;
  fs::remove_all(d);
}

TEST(SceneReader, EveryExampleSceneLoadsForItsSensor) {
  const std::pair<const char*, const char*> examples[] = {{"plane", "ls-conventional"},
                                                          {"tilted", "ls-conventional"},
                                                          {"step", "ls-conventional"},
                                                          {"depth-map", "ls-conventional"},
                                                          {"ls-demodulation-plane", "ls-demodulation"},
                                                          {"ls-demodulation-depth-map", "ls-demodulation"},
                                                          {"tof-lockin-plane", "tof-lockin"},
                                                          {"tof-lockin-step", "tof-lockin"},
                                                          {"tof-lockin-depth-map", "tof-lockin"},
                                                          {"tof-spad-plane", "tof-spad"},
                                                          {"tof-spad-step", "tof-spad"},
                                                          {"tof-spad-depth-map", "tof-spad"}};
  for (const auto& [name, sensor] : examples) {
    const sc::Scene s = sc::load_scene(kScenes + "/" + name + ".toml", sensor);
    EXPECT_EQ(s.name, name);
    EXPECT_EQ(s.sensor, sensor);
  }
  // Another sensor's scene loads; the keys that do not belong are notes naming file, line and key.
  const sc::Scene other = sc::load_scene(kScenes + "/plane.toml", "tof-spad");
  ASSERT_FALSE(other.notes.empty());
  EXPECT_NE(other.notes.front().find("plane.toml:"), std::string::npos) << other.notes.front();
  EXPECT_NE(other.notes.front().find("is not used by tof-spad"), std::string::npos) << other.notes.front();
}

TEST(SceneReader, DepthMapPathIsRelativeToTheSceneAndKeysAreChecked) {
  const fs::path d = temp_dir();
  fs::create_directories(d / "maps");
  write_bytes(d / "maps" / "m.pgm", "P2 2 2 4 0 4 4 0\n");
  const std::string good =
      "[scene]\nname = \"m\"\n[target]\nshape = \"depth_map\"\ndepth_map_file = \"maps/m.pgm\"\n"
      "depth_near_m = 2.0\ndepth_far_m = 3.0\n[rates]\nsignal_Hz = 1e4\n";
  const sc::Scene s = sc::load_scene_text(good, (d / "s.toml").string(), "tof-spad");
  ASSERT_TRUE(s.depth_map);
  EXPECT_DOUBLE_EQ(s.depth_map->at(1, 0), 3.0);
  EXPECT_DOUBLE_EQ(s.distance_m, 2.0);  // the nearest point of the map
  std::string e = error_of([&] { sc::load_scene_text(good, (d / "other" / "s.toml").string(), "tof-spad"); });
  EXPECT_NE(e.find("target.depth_map_file"), std::string::npos) << e;
  EXPECT_NE(e.find("cannot read the depth-map image"), std::string::npos) << e;
  std::string t = good;
  t.replace(t.find("depth_far_m = 3.0\n"), 18, "");
  e = error_of([&] { sc::load_scene_text(t, (d / "s.toml").string(), "tof-spad"); });
  EXPECT_NE(e.find("missing key 'target.depth_far_m'"), std::string::npos) << e;
  EXPECT_NE(e.find("[0.01, 10000]"), std::string::npos) << e;
  t = good;
  t.replace(t.find("depth_near_m = 2.0"), 18, "depth_near_m = -2.0");
  e = error_of([&] { sc::load_scene_text(t, (d / "s.toml").string(), "tof-spad"); });
  EXPECT_NE(e.find("s.toml:6: target.depth_near_m = -2 is out of range; allowed: [0.01, 10000]"), std::string::npos)
      << e;
  t = good + "[camera]\nf_number = 2\n";  // every sensor's lens F# (physical scenes)
  EXPECT_TRUE(sc::load_scene_text(t, (d / "s.toml").string(), "tof-spad").has("camera.f_number"));
  t = good + "[camera]\nfill_factor = 0.5\n";  // a key of other sensors' scenes: a note
  EXPECT_FALSE(sc::load_scene_text(t, (d / "s.toml").string(), "tof-spad").notes.empty());
  t = good;
  t.replace(t.find("shape = \"depth_map\""), 19, "shape = \"cube\"");
  e = error_of([&] { sc::load_scene_text(t, "x.toml", "tof-spad"); });
  EXPECT_NE(e.find("target.shape = \"cube\" is not allowed for tof-spad; allowed: plane, step, depth_map"),
            std::string::npos)
      << e;
  // Garbage never escapes as anything but UserError (the fuzzing contract).
  for (const char* junk :
       {"", "[[x]]", "a = [1, {b = 2}]", "[target]\nshape = 3", "\xff\xfe", "[scene]\nname = \"../x\""})
    EXPECT_THROW(sc::load_scene_text(junk, "junk.toml", "ls-conventional"), rangesim::UserError) << junk;
  fs::remove_all(d);
}

TEST(SceneOptics, FlatDepthMapGivesThePlaneGroundTruth) {
  const rangesim::LsConventionalConfig cfg =
      rangesim::ls_conventional_from_params(rangesim::load_preset("ls-conventional"));
  const fs::path d = temp_dir();
  write_bytes(d / "flat.pgm", "P2 3 3 10 5 5 5 5 5 5 5 5 5\n");  // 1.0 + 0.5 x (1.2 - 1.0) = 1.1 m everywhere
  const std::string radiometry =
      "reflectance = 0.5\n[beam]\npower_W = 0.5\nreference_distance_m = 1.1\ncolumn_offset_px = 0.37\n"
      "[background]\nirradiance_W_per_m2 = 5.0\n[camera]\nf_number = 1.4\nfill_factor = 0.5\n"
      "responsivity_A_per_W = 0.4\n";
  const sc::Scene map = sc::load_scene_text(
      "[scene]\nname = \"m\"\n[target]\nshape = \"depth_map\"\ndepth_map_file = \"flat.pgm\"\n"
      "depth_near_m = 1.0\ndepth_far_m = 1.2\n" +
          radiometry,
      (d / "m.toml").string(), "ls-conventional");
  const sc::Scene plane =
      sc::load_scene_text("[scene]\nname = \"p\"\n[target]\nshape = \"plane\"\ndistance_m = 1.1\n" + radiometry,
                          (d / "p.toml").string(), "ls-conventional");
  const sc::SceneOptics om(cfg, map), op(cfg, plane);
  int visible = 0;
  for (int b = 0; b < om.beam_positions(); b += 37)
    for (int r = 0; r < om.rows(); r += 61) {
      const sc::RowTruth tm = om.truth(b, r), tp = op.truth(b, r);
      EXPECT_EQ(tm.visible, tp.visible) << b << " " << r;
      if (!tp.visible) continue;
      ++visible;
      EXPECT_NEAR(tm.range_m, tp.range_m, 1e-12);
      EXPECT_NEAR(tm.centre_px, tp.centre_px, 1e-9);
      EXPECT_NEAR(tm.signal_V, tp.signal_V, 1e-12);
    }
  EXPECT_GT(visible, 20);
  fs::remove_all(d);
}

TEST(SceneOptics, DepthMapTruthLiesOnTheMap) {
  // The dome example: every visible lit point's depth equals the resampled map at its column
  // (the fixed point of the triangulation), within the bisection's tolerance.
  const rangesim::LsConventionalConfig cfg =
      rangesim::ls_conventional_from_params(rangesim::load_preset("ls-conventional"));
  const sc::Scene s = sc::load_scene(kScenes + "/depth-map.toml", "ls-conventional");
  const sc::SceneOptics o(cfg, s);
  int visible = 0;
  double zmin = 1e9, zmax = 0;
  for (int b = 0; b < o.beam_positions(); b += 5)
    for (int r = 0; r < o.rows(); r += 9) {
      const sc::RowTruth t = o.truth(b, r);
      if (!t.visible) continue;
      ++visible;
      const int c0 = static_cast<int>(std::floor(t.centre_px));
      const int c1 = std::min(c0 + 1, o.columns() - 1);
      const double f = t.centre_px - c0;
      const double z =
          (1 - f) * s.map_depth_m(r, c0, o.rows(), o.columns()) + f * s.map_depth_m(r, c1, o.rows(), o.columns());
      EXPECT_NEAR(t.range_m, z, 1e-9) << b << " " << r;
      zmin = std::min(zmin, t.range_m), zmax = std::max(zmax, t.range_m);
    }
  EXPECT_GT(visible, 500);
  EXPECT_LT(zmin, 1.0);   // the dome's top is seen
  EXPECT_GT(zmax, 1.12);  // and the background around it
}

TEST(SceneOptics, CameraRadiometryComesFromThePresetUnlessTheSceneOverridesIt) {
  rangesim::LsConventionalConfig cfg = rangesim::ls_conventional_from_params(rangesim::load_preset("ls-conventional"));
  const std::string base =
      "[scene]\nname = \"c\"\n[target]\nshape = \"plane\"\ndistance_m = 1.0\nreflectance = 0.5\n"
      "[beam]\npower_W = 0.5\nreference_distance_m = 1.1\n[background]\nirradiance_W_per_m2 = 5.0\n";
  const sc::Scene preset_only = sc::load_scene_text(base, "c.toml", "ls-conventional");
  const sc::Scene same = sc::load_scene_text(
      base + "[camera]\nf_number = 1.4\nfill_factor = 0.5\nresponsivity_A_per_W = 0.4\n", "c.toml", "ls-conventional");
  const sc::Scene slower = sc::load_scene_text(base + "[camera]\nf_number = 2.8\n", "c.toml", "ls-conventional");
  ASSERT_DOUBLE_EQ(cfg.optics.f_number, 1.4);  // presets/ls-conventional.toml
  ASSERT_DOUBLE_EQ(cfg.pixel.fill_factor, 0.5);
  ASSERT_DOUBLE_EQ(cfg.pixel.responsivity_A_per_W, 0.4);
  const sc::RowTruth a = sc::SceneOptics(cfg, preset_only).truth(100, 100),
                     b = sc::SceneOptics(cfg, same).truth(100, 100), c = sc::SceneOptics(cfg, slower).truth(100, 100);
  EXPECT_DOUBLE_EQ(a.signal_V, b.signal_V);
  EXPECT_DOUBLE_EQ(a.background_V, b.background_V);
  EXPECT_NEAR(c.signal_V, a.signal_V / 4, 1e-12 * a.signal_V);  // lens area ~ 1 / F#^2
  EXPECT_NEAR(c.background_V, a.background_V / 4, 1e-12 * a.background_V);
  cfg.pixel.fill_factor = 0.25;  // the preset's value is used when the scene is silent
  EXPECT_NEAR(sc::SceneOptics(cfg, preset_only).truth(100, 100).signal_V, a.signal_V / 2, 1e-12 * a.signal_V);
  EXPECT_DOUBLE_EQ(sc::SceneOptics(cfg, same).truth(100, 100).signal_V, a.signal_V);
}
