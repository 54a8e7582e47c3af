// End-to-end: `simulate` through the rangesim binary. Files, JSON keys, timing beside golden,
// errors and exit codes, and a VCD waveform.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "run_command.h"

namespace fs = std::filesystem;

namespace {

const std::string kDriver = SIMULATE_DRIVER_BIN;
const std::string kScenes = RANGESIM_SCENE_DIR;

CommandResult simulate(const std::string& args) {
  return run_command("SYSTEMC_DISABLE_COPYRIGHT_MESSAGE=1 " + kDriver + " simulate ls-conventional " + args);
}

std::string slurp(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

TEST(SimulateCommand, KernelRangeMapJsonAndFiles) {
  const std::string dir = make_temp_dir();
  const CommandResult r =
      simulate("--scene " + kScenes + "/plane.toml --frames 40 --kernel-only --json --points --out " + dir + "/o");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  for (const char* key : {"frame_time_s", "frame_rate_Hz", "cycles", "range_error_rms_m", "range_error_rms_px",
                          "phases", "golden", "frame_cycles", "points_detected"})
    EXPECT_TRUE(j.contains(key)) << key;
  EXPECT_EQ(j["cycles"].get<long long>(), 40 * 100);
  EXPECT_NEAR(j["frame_rate_Hz"].get<double>(), 394.5e3, 1e-6);
  EXPECT_TRUE(j["timing_matches_golden"].get<bool>());
  EXPECT_EQ(j["phases"].size(), 5U);
  EXPECT_GT(j["points_detected"].get<long long>(), 40 * 300);
  EXPECT_LT(j["range_error_rms_px"].get<double>(), 0.3);
  EXPECT_LT(j["range_error_rms_m"].get<double>(), 5e-3);
  // The default file choice: the range map (365 x 40 = 14,600 values) stays CSV, points (about
  // 14,600 rows x 11 columns) go to .npy.
  for (const char* f : {"range_map.csv", "points.npy", "frames.csv", "summary.json"})
    EXPECT_TRUE(fs::exists(dir + "/o/" + f)) << f;
  for (const char* f : {"range_map.npy", "points.csv"}) EXPECT_FALSE(fs::exists(dir + "/o/" + f)) << f;
  const std::string frames = slurp(dir + "/o/frames.csv");
  EXPECT_EQ(std::count(frames.begin(), frames.end(), '\n'), 41);
  EXPECT_NE(frames.find("\n0,0,100,100,4,4,8,72,12,"), std::string::npos) << frames.substr(0, 200);
  fs::remove_all(dir);
}

TEST(SimulateCommand, PointsTableOnlyOnRequestFilesOnAnyThreads) {
  // The per-point table is written with --points only; the run says how to get it. The files are
  // written side by side on --threads threads: the same bytes on one.
  const std::string dir = make_temp_dir();
  const std::string base = "--scene " + kScenes + "/plane.toml --frames 10 --kernel-only";
  const CommandResult plain = simulate(base + " --threads 2 --out " + dir + "/a");
  ASSERT_EQ(plain.exit_code, 0) << plain.err;
  EXPECT_NE(plain.out.find("(per-point table not written: add --points)"), std::string::npos) << plain.out;
  for (const char* f : {"points.csv", "points.npy"}) EXPECT_FALSE(fs::exists(dir + "/a/" + f)) << f;
  const CommandResult one = simulate(base + " --threads 1 --out " + dir + "/b");
  ASSERT_EQ(one.exit_code, 0) << one.err;
  for (const char* f : {"range_map.csv", "confidence_map.csv", "frames.csv", "range_map.png", "range_error.png"}) {
    EXPECT_TRUE(fs::exists(dir + "/a/" + f)) << f;
    EXPECT_EQ(slurp(dir + "/a/" + f), slurp(dir + "/b/" + f)) << f;
  }
  const CommandResult with = simulate(base + " --points --out " + dir + "/c");
  ASSERT_EQ(with.exit_code, 0) << with.err;
  EXPECT_NE(with.out.find("wrote " + dir + "/c/points.csv"), std::string::npos) << with.out;
  EXPECT_EQ(with.out.find("--points)"), std::string::npos) << with.out;
  const std::string points = slurp(dir + "/c/points.csv");
  EXPECT_EQ(points.rfind("frame,beam_position,row,", 0), 0U) << points.substr(0, 80);
  EXPECT_GT(std::count(points.begin(), points.end(), '\n'), 1);
  // A sensor without a points table has nothing to offer.
  const CommandResult lockin = run_command(kDriver + " simulate tof-lockin --scene " + kScenes +
                                           "/tof-lockin-plane.toml --kernel-only --no-plots --out " + dir + "/d");
  ASSERT_EQ(lockin.exit_code, 0) << lockin.err;
  EXPECT_EQ(lockin.out.find("--points"), std::string::npos) << lockin.out;
  fs::remove_all(dir);
}

TEST(SimulateCommand, SystemCEqualsKernelAndWritesTrace) {
  const std::string dir = make_temp_dir();
  const std::string scene = kScenes + "/step.toml";
  const CommandResult k =
      simulate("--scene " + scene + " --frames 3 --kernel-only --json --no-plots --points --out " + dir + "/k");
  const CommandResult s = simulate("--scene " + scene + " --frames 3 --json --no-plots --points --trace " + dir +
                                   "/w.vcd --out " + dir + "/s");
  ASSERT_EQ(k.exit_code, 0) << k.err;
  ASSERT_EQ(s.exit_code, 0) << s.err;
  const auto jk = nlohmann::json::parse(k.out), js = nlohmann::json::parse(s.out);
  EXPECT_EQ(js["harness"], "systemc");
  EXPECT_EQ(js["sc_errors"].get<long long>(), 0);
  EXPECT_EQ(js["cycles"], jk["cycles"]);
  EXPECT_EQ(js["range_error_rms_m"], jk["range_error_rms_m"]);
  EXPECT_EQ(slurp(dir + "/k/points.csv"), slurp(dir + "/s/points.csv"));
  EXPECT_NEAR(js["frame_time_s"].get<double>(), jk["frame_time_s"].get<double>(),
              1e-7 * jk["frame_time_s"].get<double>());
  const std::string vcd = slurp(dir + "/w.vcd");
  EXPECT_NE(vcd.find("$enddefinitions"), std::string::npos);
  EXPECT_NE(vcd.find("search_start"), std::string::npos);
  for (const auto& e : fs::directory_iterator(dir)) EXPECT_EQ(e.path().string().find(".partial"), std::string::npos);
  fs::remove_all(dir);
}

TEST(SimulateCommand, BadInputExitsTwoAndWritesNothing) {
  const std::string dir = make_temp_dir();
  struct Case {
    std::string args, message;
  };
  const Case cases[] = {
      {"--scene " + dir + "/missing.toml --kernel-only", "cannot read scene file"},
      {"--scene " + kScenes + "/plane.toml --frames 0 --kernel-only", "--frames 0: allowed 1 <= N"},
      {"--scene " + kScenes + "/plane.toml --kernel-only --trace " + dir + "/x.vcd", "--trace needs the SystemC model"},
      {"--scene " + kScenes + "/plane.toml --trace " + dir + "/x.txt", "must end in .vcd"},
      {"--scene " + kScenes + "/plane.toml --tick", "use it with --kernel-only"},
  };
  for (const Case& c : cases) {
    const CommandResult r = simulate(c.args + " --out " + dir + "/o");
    EXPECT_EQ(r.exit_code, 2) << c.args << "\n" << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir + "/o")) << c.args;
  }
  std::ofstream(dir + "/bad.toml") << "[scene]\nname = \"b\"\n[target]\nshape = \"plane\"\ndistance_m = -1\n";
  const CommandResult r = simulate("--scene " + dir + "/bad.toml --kernel-only --out " + dir + "/o");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.err.find("bad.toml:5: target.distance_m = -1 is out of range; allowed: [0.01, 10000]"), std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(dir + "/o"));
  // A light-section scene runs on tof-spad: its light-section keys are notes naming the file.
  const CommandResult m = run_command(kDriver + " simulate tof-spad --scene " + kScenes +
                                      "/plane.toml --kernel-only --frames 1 --out " + dir + "/m");
  EXPECT_EQ(m.exit_code, 0) << m.err;
  EXPECT_NE(m.err.find("note: " + kScenes + "/plane.toml"), std::string::npos) << m.err;
  fs::remove_all(dir);
}

TEST(SimulateCommand, TickingEqualsEventSkippingEndToEnd) {
  const std::string dir = make_temp_dir();
  const std::string base = "--scene " + kScenes + "/tilted.toml --frames 8 --kernel-only --no-plots --points --json";
  const CommandResult a = simulate(base + " --out " + dir + "/a");
  const CommandResult b = simulate(base + " --tick --out " + dir + "/b");
  const CommandResult d = simulate(base + " --dense --out " + dir + "/d");
  ASSERT_EQ(a.exit_code, 0) << a.err;
  ASSERT_EQ(b.exit_code, 0) << b.err;
  ASSERT_EQ(d.exit_code, 0) << d.err;
  EXPECT_EQ(slurp(dir + "/a/points.csv"), slurp(dir + "/b/points.csv"));
  EXPECT_EQ(slurp(dir + "/a/frames.csv"), slurp(dir + "/b/frames.csv"));
  EXPECT_EQ(slurp(dir + "/a/points.csv"), slurp(dir + "/d/points.csv"));
  fs::remove_all(dir);
}

TEST(SimulateCommand, MapFilesBegunDuringTheRunEqualThoseWrittenAfterIt) {
  // On two threads a map that goes out as .npy has its files and images begun while the run scores
  // it against its truth (SimulationHost::map_ready, truth_ready); on one thread all are written
  // after the run. The same bytes either way, listed in the same order.
  const std::string dir = make_temp_dir();
  const std::string base = "--scene " + kScenes + "/tilted.toml --frames 60 --seed 3 --kernel-only --npy --points";
  const CommandResult two = simulate(base + " --threads 2 --out " + dir + "/two");
  const CommandResult one = simulate(base + " --threads 1 --out " + dir + "/one");
  ASSERT_EQ(two.exit_code, 0) << two.err;
  ASSERT_EQ(one.exit_code, 0) << one.err;
  const auto listed = [](const std::string& out, const std::string& folder) {
    std::vector<std::string> files;
    std::istringstream lines(out);
    for (std::string line; std::getline(lines, line);)
      if (const auto at = line.find("wrote " + folder + "/"); at != std::string::npos)
        files.push_back(line.substr(at + 7 + folder.size()));
    return files;
  };
  const std::vector<std::string> files = listed(two.out, dir + "/two");
  EXPECT_EQ(files, listed(one.out, dir + "/one"));
  EXPECT_EQ(files, (std::vector<std::string>{"range_map.npy", "confidence_map.npy", "range_map.png", "range_error.png",
                                             "points.npy", "frames.csv", "summary.json"}));
  for (const std::string& f : files) {
    if (f == "summary.json") continue;  // its run times differ
    EXPECT_EQ(slurp(dir + "/two/" + f), slurp(dir + "/one/" + f)) << f;
  }
  // Begun during the run on two threads only; what that took is counted with the output's CPU (it
  // may be 0 on a loaded machine, where the helper had not run yet when the run ended).
  const CommandResult two_json = simulate(base + " --threads 2 --json --force --out " + dir + "/two");
  const CommandResult one_json = simulate(base + " --threads 1 --json --force --out " + dir + "/one");
  ASSERT_EQ(two_json.exit_code, 0) << two_json.err;
  ASSERT_EQ(one_json.exit_code, 0) << one_json.err;
  const auto j2 = nlohmann::json::parse(two_json.out), j1 = nlohmann::json::parse(one_json.out);
  EXPECT_TRUE(j2["output_begun_during_run"].get<bool>());
  EXPECT_FALSE(j1["output_begun_during_run"].get<bool>());
  EXPECT_GE(j2["output_cpu_during_run_s"].get<double>(), 0);
  EXPECT_GE(j2["output_cpu_s"].get<double>(), j2["output_cpu_during_run_s"].get<double>());
  EXPECT_EQ(j1["output_cpu_during_run_s"].get<double>(), 0);
  fs::remove_all(dir);
}

TEST(SimulateCommand, ThreadsGiveTheSameFilesAndAreCheckedPerSensor) {
  // --threads N gives each kernel thread consecutive frame accesses: the files are byte-identical
  // for any count (including one that does not divide the frames); summary.json says how many ran.
  const std::string dir = make_temp_dir();
  const std::string base =
      "--scene " + kScenes + "/tilted.toml --frames 7 --kernel-only --no-plots --npy --points --json";
  const CommandResult one = simulate(base + " --threads 1 --out " + dir + "/one");
  const CommandResult three = simulate(base + " --threads 3 --out " + dir + "/three");
  ASSERT_EQ(one.exit_code, 0) << one.err;
  ASSERT_EQ(three.exit_code, 0) << three.err;
  EXPECT_EQ(nlohmann::json::parse(one.out)["threads"].get<int>(), 1);
  EXPECT_EQ(nlohmann::json::parse(three.out)["threads"].get<int>(), 3);
  for (const char* f : {"range_map.npy", "confidence_map.npy", "points.npy", "frames.csv"})
    EXPECT_EQ(slurp(dir + "/one/" + f), slurp(dir + "/three/" + f)) << f;
  struct Case {
    std::string command, message;
  };
  const std::string plane = " --scene " + kScenes + "/plane.toml --frames 2 --out " + dir + "/o";
  const Case cases[] = {
      {"ls-conventional --kernel-only --threads 0" + plane, "--threads"},
      {"ls-conventional --kernel-only --threads 2000" + plane, "--threads"},
      {"ls-conventional --threads 2" + plane, "--threads: the SystemC model runs on one thread; add --kernel-only"},
      {"tof-spad --kernel-only --threads 2" + plane,
       "--threads 2: the tof-spad kernel runs on one thread; allowed with ls-conventional (or 1)"},
  };
  for (const Case& c : cases) {
    const CommandResult r = run_command(kDriver + " simulate " + c.command);
    EXPECT_EQ(r.exit_code, 2) << c.command << "\n" << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir + "/o")) << c.command;
  }
  fs::remove_all(dir);
}
