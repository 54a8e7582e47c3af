// rangesim sweep and merge end to end: variants, invalid variants as rows, 3-way shards merged
// byte-identical to one process, a killed sweep resumed byte-identical, bad --vary refused.
#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <thread>

#include "run_command.h"

extern char** environ;

namespace {

namespace fs = std::filesystem;
const std::string kBin = RANGESIM_BIN;

// 2 x 3 variants of ls-conventional on a small grid; one column count the address cannot reach.
const std::string kSweep =
    "sweep ls-conventional --vary multisampling.samplings=1:4:2 --vary pixel.columns=300,375,1024 "
    "--set evaluation.signal_points=9 --set evaluation.background_points=7 --no-plots";

std::map<std::string, std::string> files_of(const std::string& dir) {
  std::map<std::string, std::string> m;
  for (const auto& e : fs::directory_iterator(dir)) {
    if (e.is_directory()) continue;
    std::ifstream in(e.path(), std::ios::binary);
    m[e.path().filename().string()] =
        std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  }
  return m;
}

CommandResult rangesim(const std::string& args) { return run_command(kBin + " " + args); }

TEST(Sweep, VariantsRatesAndInvalidRows) {
  const std::string dir = make_temp_dir() + "/s";
  const CommandResult r = rangesim(kSweep + " --json --out " + dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["variants_total"], 6);
  EXPECT_EQ(j["variants_valid"], 4);
  EXPECT_EQ(j["varied"], nlohmann::json({"multisampling.samplings", "pixel.columns"}));
  const auto& v = j["variants"];
  EXPECT_EQ(v[0]["multisampling.samplings"], "1");
  EXPECT_EQ(v[2]["pixel.columns"], "1024");
  EXPECT_FALSE(v[2]["valid"].get<bool>());
  EXPECT_NE(v[2]["reason"].get<std::string>().find("timing.address_bits = 9 cannot address pixel.columns = 1024"),
            std::string::npos);
  // Frame rate from the clock schedule: 4 + N (1 + 2 + 18) + 12 cycles at 39.45 MHz.
  EXPECT_NEAR(v[0]["frame_access_rate_Hz"].get<double>(), 39.45e6 / 37, 1e-6);
  EXPECT_NEAR(v[3]["frame_access_rate_Hz"].get<double>(), 39.45e6 / 100, 1e-6);
  // More samplings: slower, and a better best accuracy.
  EXPECT_LT(v[4]["accuracy_min_m"].get<double>(), v[1]["accuracy_min_m"].get<double>());
  EXPECT_TRUE(fs::exists(dir + "/sweep.csv"));
  EXPECT_FALSE(fs::exists(dir + "/.staging-sweep/sweep.1-of-1.journal"));  // removed on completion
}

TEST(Sweep, ThreeShardsMergeByteIdenticalToOneProcess) {
  const std::string tmp = make_temp_dir();
  ASSERT_EQ(rangesim(kSweep + " --out " + tmp + "/one").exit_code, 0);
  std::string parts;
  for (int k = 1; k <= 3; ++k) {
    const std::string d = tmp + "/part" + std::to_string(k);
    const CommandResult r = rangesim(kSweep + " --shard " + std::to_string(k) + "/3 --out " + d);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    parts += " " + d + "/sweep.shard-" + std::to_string(k) + "-of-3.json";
  }
  const CommandResult m = rangesim("merge --no-plots --out " + tmp + "/merged" + parts);
  ASSERT_EQ(m.exit_code, 0) << m.err;
  EXPECT_EQ(files_of(tmp + "/merged"), files_of(tmp + "/one"));
  // A missing or repeated shard, or one of another sweep, is refused.
  const std::string p1 = tmp + "/part1/sweep.shard-1-of-3.json", p2 = tmp + "/part2/sweep.shard-2-of-3.json";
  const CommandResult missing = rangesim("merge --out " + tmp + "/x " + p1 + " " + p2);
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.err.find("shards missing: 3/3"), std::string::npos) << missing.err;
  const CommandResult twice = rangesim("merge --out " + tmp + "/x " + p1 + " " + p1);
  EXPECT_NE(twice.err.find("given twice"), std::string::npos) << twice.err;
  ASSERT_EQ(rangesim(kSweep + " --set timing.clock_Hz=20e6 --shard 3/3 --out " + tmp + "/other").exit_code, 0);
  const CommandResult other =
      rangesim("merge --out " + tmp + "/x " + p1 + " " + p2 + " " + tmp + "/other/sweep.shard-3-of-3.json");
  EXPECT_NE(other.err.find("shard of another sweep"), std::string::npos) << other.err;
  EXPECT_FALSE(fs::exists(tmp + "/x/sweep.csv"));
}

TEST(Sweep, MonteCarloAccuracyWithItsIntervalPerVariant) {
  const std::string dir = make_temp_dir() + "/mc";
  const CommandResult r = rangesim("sweep ls-conventional --vary multisampling.samplings=1,4 --set evaluation.signal_points=3 "
                                   "--set evaluation.background_points=2 --trials 300 --json --no-plots --out " + dir);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const auto j = nlohmann::json::parse(r.out);
  for (const auto& v : j["variants"]) {
    ASSERT_TRUE(v["mc_accuracy_min_m"].is_number()) << v;
    const double lo = v["mc_accuracy_min_lo_m"], mid = v["mc_accuracy_min_m"], hi = v["mc_accuracy_min_hi_m"];
    EXPECT_LE(lo, mid);
    EXPECT_LE(mid, hi);
    EXPECT_LE(v["mc_accuracy_min_m"].get<double>(), v["mc_accuracy_max_m"].get<double>());
    EXPECT_EQ(v["mc_points"], v["points_detectable"]);
  }
  // Four samplings: a smaller Monte Carlo accuracy at the best point, as golden says.
  EXPECT_LT(j["variants"][1]["mc_accuracy_min_m"].get<double>(), j["variants"][0]["mc_accuracy_min_m"].get<double>());
}

int journal_records(const std::string& dir) {
  std::ifstream in(dir + "/.staging-sweep/sweep.1-of-1.journal");
  int n = 0;
  for (std::string l; std::getline(in, l);) n += l.rfind("P ", 0) == 0;
  return n;
}

TEST(Sweep, KilledSweepResumesByteIdentical) {
  const std::string tmp = make_temp_dir();
  // The preset's full 61 x 61 grid: each variant takes long enough to be killed between them. The
  // fixed 16-position sub-pixel rule keeps each variant a few seconds (the adaptive one, a minute).
  const std::string sweep =
      "sweep ls-conventional --vary multisampling.samplings=1:6:6 --set evaluation.subpixel_tolerance=0 --no-plots";
  ASSERT_EQ(rangesim(sweep + " --out " + tmp + "/ref").exit_code, 0);
  std::vector<std::string> parts = {kBin};
  for (const char* a : {"sweep", "ls-conventional", "--vary", "multisampling.samplings=1:6:6", "--set",
                        "evaluation.subpixel_tolerance=0", "--no-plots", "--out"})
    parts.push_back(a);
  parts.push_back(tmp + "/k");
  std::vector<char*> argv;
  for (auto& s : parts) argv.push_back(s.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_addopen(&fa, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&fa, 2, "/dev/null", O_WRONLY, 0);
  pid_t pid = -1;
  ASSERT_EQ(posix_spawn(&pid, kBin.c_str(), &fa, nullptr, argv.data(), environ), 0);
  const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(120);
  while (journal_records(tmp + "/k") < 2 && std::chrono::steady_clock::now() < until)
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  ASSERT_EQ(kill(pid, SIGKILL), 0);
  int status = 0;
  waitpid(pid, &status, 0);
  const int kept = journal_records(tmp + "/k");
  ASSERT_GE(kept, 2);
  if (kept < 6) EXPECT_FALSE(fs::exists(tmp + "/k/sweep.csv"));  // nothing final from the killed run
  const CommandResult r = rangesim(sweep + " --out " + tmp + "/k --resume");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_EQ(files_of(tmp + "/k"), files_of(tmp + "/ref"));
}

TEST(Sweep, BadVaryIsRefusedNamingTheKeyAndWritesNothing) {
  const std::string dir = make_temp_dir() + "/bad";
  const auto bad = [&](const std::string& vary) {
    return rangesim("sweep ls-conventional --vary " + vary + " --out " + dir);
  };
  for (const auto& [vary, fragment] : std::vector<std::pair<std::string, std::string>>{
           {"timing.clok_Hz=1,2", "no parameter 'timing.clok_Hz' for sensor ls-conventional"},
           {"timing.clock_Hz=1:2", "expected KEY=LO:HI:N[:log]"},
           {"timing.clock_Hz=2e6:1e6:3", "LO = 2e+06 > HI = 1e+06"},
           {"timing.clock_Hz=0:1e6:3:log", "needs LO > 0"},
           {"timing.clock_Hz=1e6:2e6:0", "N = 0 must be an integer in [1, 100000]"},
           {"comparator.threshold_mode=1:2:3", "is not a number; give a list"},
           {"timing.clock_Hz=1e6,,2e6", "an empty value"},
           {"multisampling.samplings=1,65", "--vary multisampling.samplings=65: multisampling.samplings = 65 is out of range; allowed: integer in [1, 64]"},
           {"comparator.threshold_mode=tracking,best", "is not allowed; allowed: one of \"tracking\" \"fixed\""}}) {
    const CommandResult r = bad(vary);
    EXPECT_EQ(r.exit_code, 2) << vary;
    EXPECT_NE(r.err.find(fragment), std::string::npos) << vary << ": " << r.err;
  }
  const CommandResult zip = rangesim(
      "sweep ls-conventional --zip --vary timing.clock_Hz=1e6,2e6 --vary "
      "multisampling.samplings=1,2,3 --out " +
      dir);
  EXPECT_NE(zip.err.find("--zip: --vary timing.clock_Hz has 2 values"), std::string::npos) << zip.err;
  EXPECT_FALSE(fs::exists(dir));
}

}  // namespace
