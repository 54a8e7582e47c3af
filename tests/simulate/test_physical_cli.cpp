// End-to-end through the rangesim binary: every example scene on every sensor (a few frames each),
// scene keys of other sensors as notes, physical values out of range as exit 2, the physical axes
// of `evaluate` and the `compare` command's files and content.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "run_command.h"

namespace fs = std::filesystem;

namespace {

const std::string kDriver = std::string("SYSTEMC_DISABLE_COPYRIGHT_MESSAGE=1 ") + SIMULATE_DRIVER_BIN;
const std::string kScenes = RANGESIM_SCENE_DIR;

std::string slurp(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

const char* const kSensors[] = {"ls-conventional", "ls-demodulation", "tof-lockin", "tof-spad"};

// Few frames: the run's length is not what is tested here.
std::string short_run(const std::string& sensor) {
  if (sensor == "ls-conventional") return "--frames 8 --kernel-only";
  if (sensor == "ls-demodulation") return "--frames 4 --kernel-only";
  if (sensor == "tof-lockin") return "--frames 2 --kernel-only";
  return "--frames 1 --kernel-only";
}

class EveryScene : public ::testing::TestWithParam<const char*> {};

}  // namespace

// Every example scene runs on every sensor: exit 0, a summary, and the other sensors' keys noted.
TEST_P(EveryScene, RunsOnEverySensor) {
  const std::string dir = make_temp_dir();
  const std::string scene = kScenes + "/" + GetParam() + ".toml";
  for (const char* sensor : kSensors) {
    const CommandResult r = run_command(kDriver + " simulate " + sensor + " --scene " + scene + " " +
                                        short_run(sensor) + " --json --out " + dir + "/" + sensor);
    ASSERT_EQ(r.exit_code, 0) << sensor << " on " << scene << ":\n" << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_TRUE(j.contains("frame_rate_Hz")) << sensor;
    if (j.contains("scene_notes")) {
      EXPECT_NE(r.err.find("rangesim simulate: note: "), std::string::npos) << sensor << r.err;
    }
  }
  fs::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(Scenes, EveryScene,
                         ::testing::Values("plane", "tilted", "step", "depth-map", "sunlit-wall",
                                           "ls-demodulation-plane", "ls-demodulation-depth-map", "tof-lockin-plane",
                                           "tof-lockin-step", "tof-lockin-depth-map", "tof-spad-plane",
                                           "tof-spad-step", "tof-spad-depth-map", "tof-spad-spot", "objects"),
                         [](const auto& info) {
                           std::string n = info.param;
                           for (auto& c : n)
                             if (c == '-') c = '_';
                           return n;
                         });

// A key the sensor cannot use is a note (exit 0); a physical value out of range is exit 2 naming
// the key and its range, with nothing written.
TEST(PhysicalScene, NotesAndOutOfRangeExit2) {
  const std::string dir = make_temp_dir();
  CommandResult r = run_command(kDriver + " simulate ls-conventional --scene " + kScenes +
                                "/tof-spad-plane.toml --frames 4 --kernel-only --out " + dir + "/a");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_NE(r.err.find("note: " + kScenes + "/tof-spad-plane.toml:"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("rates.signal_Hz is not used by ls-conventional"), std::string::npos) << r.err;
  std::string text = slurp(kScenes + "/sunlit-wall.toml");
  const auto bad = [&](const std::string& from, const std::string& to) {
    std::string t = text;
    t.replace(t.find(from), from.size(), to);
    std::ofstream(dir + "/bad.toml") << t;
    return dir + "/bad.toml";
  };
  r = run_command(kDriver + " simulate tof-lockin --scene " + bad("reflectance = 0.5", "reflectance = -0.5") +
                  " --out " + dir + "/b");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("target.reflectance = -0.5 is out of range; allowed: (0, 1]"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir + "/b/summary.json"));
  r = run_command(kDriver + " simulate tof-spad --scene " +
                  bad("illuminance_lux = 10000.0", "illuminance_lux = -1") + " --out " + dir + "/c");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("ambient.illuminance_lux = -1 is out of range; allowed: [0, 1e+06]"), std::string::npos)
      << r.err;
  r = run_command(kDriver + " simulate tof-spad --scene " +
                  bad("beam = \"sheet\"", "beam = \"spot\"\n[beam]\nfirst_column = 127\ncolumns = 4") + " --out " +
                  dir + "/d");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("beam.first_column = 127 puts the spot outside the 128 x 128 array of tof-spad; allowed 0 <= "
                       "value <= 124"),
            std::string::npos)
      << r.err;
  fs::remove_all(dir);
}

// evaluate on the physical axes: the grid in lux and watts, the ranges back in lux and watts.
TEST(PhysicalAxes, EvaluateInLuxAndWatts) {
  const std::string dir = make_temp_dir();
  CommandResult r = run_command(kDriver + " evaluate tof-lockin --background-lux 1:1e6:13 --signal-power 0.01:10:7 "
                                "--json --no-plots --out " + dir + "/e");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_TRUE(j.contains("physical_axes")) << r.out.substr(0, 500);
  const auto& p = j["physical_axes"];
  EXPECT_EQ(p["background"]["unit"], "lx");
  EXPECT_NEAR(p["background"]["lo"].get<double>(), 1.0, 1e-9);
  EXPECT_NEAR(p["background"]["hi"].get<double>(), 1e6, 1e-3);
  EXPECT_NEAR(p["signal"]["lo"].get<double>(), 0.01, 1e-12);
  EXPECT_GT(p["background_range_lux"]["hi"].get<double>(), 1.0);
  EXPECT_NE(p["radiometry"].get<std::string>().find("I = R P"), std::string::npos);
  r = run_command(kDriver + " evaluate tof-lockin --background 1e-12:1e-9:4 --background-lux 1:10:2 --out " + dir +
                  "/f");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("--background and --background-lux"), std::string::npos) << r.err;
  fs::remove_all(dir);
}

// compare: the four sensors on the default scene with a small grid; every file and its content.
TEST(Compare, SmokeFilesAndContent) {
  const std::string dir = make_temp_dir();
  const CommandResult r = run_command(kDriver + " compare --background-lux 1:1e6:13 --signal-power 1e-3:10:9 --out " +
                                      dir + "/c --json");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["sensors"].size(), 4U);
  for (const auto& s : j["sensors"]) {
    EXPECT_TRUE(s.contains("detectable_background_lux")) << s["sensor"];
    EXPECT_TRUE(s["table"].contains("background_range_dB")) << s["sensor"];
    EXPECT_EQ(s["sbr_vs_background"].size(), 13U) << s["sensor"];
    EXPECT_GT(s["table"]["range_maps_per_s"].get<double>(), 0) << s["sensor"];
  }
  EXPECT_EQ(j["scene"]["name"], "sunlit-wall");
  for (const char* f : {"report.html", "compare.json", "compare.csv", "sbr_vs_background.csv",
                        "accuracy_vs_background.csv", "fig1_4_sbr_vs_background.png", "fig1_4_sbr_vs_background.svg",
                        "accuracy_vs_background.png"})
    EXPECT_TRUE(fs::exists(dir + "/c/" + f)) << f;
  const std::string html = slurp(dir + "/c/report.html");
  EXPECT_NE(html.find("src=\"data:image/png;base64,iVBORw0KGgo"), std::string::npos);  // the PNG inline
  EXPECT_NE(html.find("Table 5.1 in physical units"), std::string::npos);
  EXPECT_EQ(html.find("src=\"http"), std::string::npos);  // self-contained: nothing referenced
  EXPECT_EQ(html.find(".png\""), std::string::npos);
  for (const char* sensor : {"ls-conventional", "ls-demodulation", "tof-lockin", "tof-spad"})
    EXPECT_NE(html.find(std::string("<td>") + sensor + "</td>"), std::string::npos) << sensor;
  const std::string csv = slurp(dir + "/c/compare.csv");
  EXPECT_EQ(csv.rfind("quantity,unit,ls-conventional,ls-demodulation,tof-lockin,tof-spad\n", 0), 0U) << csv;
  EXPECT_NE(r.err.find("compare"), std::string::npos);  // the progress line's final count
  fs::remove_all(dir);
}
