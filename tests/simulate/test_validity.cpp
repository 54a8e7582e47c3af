// Range maps that know which pixels are valid, end to end through the rangesim binary: the
// validity keys and files of every sensor, the spot scene's false valids below 1 % with every
// spot pixel still valid, and each rule biting when its preset key is turned.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "run_command.h"

namespace fs = std::filesystem;

namespace {

const std::string kScenes = RANGESIM_SCENE_DIR;

nlohmann::json simulate(const std::string& sensor, const std::string& args) {
  const CommandResult r = run_command(std::string(SIMULATE_DRIVER_BIN) + " simulate " + sensor +
                                      " --kernel-only --no-plots --json --force " + args);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  return r.exit_code == 0 ? nlohmann::json::parse(r.out) : nlohmann::json::object();
}

std::string header(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  return line;
}

}  // namespace

TEST(RangeMapValidity, SpotSceneFalseValidsBelowOnePercentSpotStillValid) {
  const std::string dir = make_temp_dir();
  const auto j = simulate("tof-spad", "--scene " + kScenes + "/tof-spad-spot.toml --points --out " + dir + "/o");
  ASSERT_TRUE(j.contains("false_valid_fraction"));
  EXPECT_GT(j["validity"]["pixels_without_echo"].get<long long>(), 400);
  EXPECT_LT(j["false_valid_fraction"].get<double>(), 0.01);
  EXPECT_EQ(j["echo_valid_fraction"].get<double>(), 1.0);
  // The estimator alone fires on most background-only pixels: the rule is what removes them.
  EXPECT_GT(j["background_only"]["detections"].get<long long>(), 100);
  EXPECT_TRUE(fs::exists(dir + "/o/confidence_map.csv"));
  EXPECT_NE(header(dir + "/o/points.csv").find(",valid,significance_sigma"), std::string::npos);
  fs::remove_all(dir);
}

TEST(RangeMapValidity, TheSpadRuleIsThePresetsDetectionSigma) {
  const std::string dir = make_temp_dir();
  const auto j = simulate("tof-spad", "--scene " + kScenes + "/tof-spad-spot.toml --set evaluation.detection_sigma=0 " +
                                          "--out " + dir + "/o");
  EXPECT_GT(j["false_valid_fraction"].get<double>(), 0.5);
  fs::remove_all(dir);
}

TEST(RangeMapValidity, LightSectionEdgeMarginRemovesClippedSpots) {
  const std::string dir = make_temp_dir();
  const std::string scene = "--scene " + kScenes + "/step.toml --csv --points --out " + dir + "/o";
  const auto with = simulate("ls-conventional", scene);
  EXPECT_EQ(with["false_valid_fraction"].get<double>(), 0.0);
  EXPECT_GT(with["echo_valid_fraction"].get<double>(), 0.999);
  EXPECT_NE(header(dir + "/o/points.csv").find(",valid,detecting_fraction"), std::string::npos);
  const auto without = simulate("ls-conventional", scene + " --set validity.edge_margin_px=0");
  EXPECT_GT(without["false_valid_fraction"].get<double>(), 0.1);
  fs::remove_all(dir);
}

TEST(RangeMapValidity, EverySensorReportsItsRule) {
  const std::string dir = make_temp_dir();
  const std::pair<const char*, const char*> runs[] = {{"ls-demodulation", "ls-demodulation-plane.toml"},
                                                      {"tof-lockin", "tof-lockin-step.toml"}};
  for (const auto& [sensor, scene] : runs) {
    const auto j = simulate(sensor, "--scene " + kScenes + "/" + scene + " --out " + dir + "/" + sensor);
    EXPECT_FALSE(j["validity"]["rule"].get<std::string>().empty()) << sensor;
    EXPECT_GT(j["valid_fraction"].get<double>(), 0.5) << sensor;
    EXPECT_TRUE(fs::exists(dir + "/" + sensor + "/confidence_map.csv")) << sensor;
  }
  // tof-lockin: raising the SNR rule past every pixel's SNR leaves no valid range.
  const auto none = simulate("tof-lockin", "--scene " + kScenes + "/tof-lockin-step.toml --set readout.min_snr=1e6 " +
                                               "--out " + dir + "/none");
  EXPECT_EQ(none["valid_fraction"].get<double>(), 0.0);
  fs::remove_all(dir);
}
