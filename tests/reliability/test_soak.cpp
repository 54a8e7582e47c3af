// Soak test: command lines drawn by a seeded generator, legal and illegal mixed (grids, integer
// flags, presets, scenes, output folders, budgets), each run through the built binary with a
// wall-time and an address-space limit. Every run must end by itself with an exit code of the
// documented set (never 1, never a signal), within its bounds, and leave nothing behind: no
// staging folder, lock or partial file, and nothing at all when it failed.
//
// SOAK_COUNT and SOAK_SEED (environment) override the defaults of the build (RANGESIM_SOAK_COUNT,
// RANGESIM_SOAK_SEED); a failure names the seed and the command line to replay.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <set>
#include <unistd.h>

#include "child_process.h"

namespace fs = std::filesystem;

namespace {

const std::string kBin = RANGESIM_BIN;
const std::string kScenes = RANGESIM_SCENE_DIR;
const std::vector<std::string> kSensors = {"ls-conventional", "ls-demodulation", "tof-lockin", "tof-spad"};
constexpr double kWallLimitS = 60;                        // a run past this is a hang
constexpr unsigned long long kAddressSpace = 4ull << 30;  // RLIMIT_AS of every run
constexpr long kMaxRssKib = 1L << 20;                     // 1 GiB resident at most

class Generator {
 public:
  explicit Generator(std::uint64_t seed) : rng_(seed) {}

  // One command line (arguments after the program name).
  std::string command() {
    const int kind = pick(100);
    if (kind < 40) return evaluate();
    if (kind < 52) return monte_carlo();
    if (kind < 70) return simulate();
    if (kind < 78) return sweep();
    if (kind < 86) return frame_rate_or_show();
    if (kind < 92) return merge();
    return cosim_flags();
  }

 private:
  std::mt19937_64 rng_;

  int pick(int n) { return static_cast<int>(rng_() % static_cast<std::uint64_t>(n)); }
  bool chance(int percent) { return pick(100) < percent; }
  template <class T>
  const T& one_of(const std::vector<T>& v) {
    return v[static_cast<std::size_t>(pick(static_cast<int>(v.size())))];
  }

  // A grid for the sensor's unit: small and legal, or one of the known bad shapes.
  std::string grid(const std::string& sensor, bool background) {
    if (chance(10))
      return one_of<std::string>({"0:1:3", "1:0.5:3", "5e-324:1e-9:3", "1e-9:1e-9:0", "1e-9:1e-9:20000", "abc", "1:2",
                                  "nan:1:3", "1e-9:inf:3", "1e-310:1e300:2", "-1:1:2"});
    const std::map<std::string, std::pair<double, double>> span = {{"ls-conventional", {1e-3, 1.5}},
                                                                   {"ls-demodulation", {1e-12, 1e-9}},
                                                                   {"tof-lockin", {1e-14, 1e-9}},
                                                                   {"tof-spad", {1e3, 1e7}}};
    const auto [lo, hi] = span.at(sensor);
    const double a = lo * std::pow(hi / lo, pick(1000) / 1000.0), b = a * std::pow(hi / a, pick(1000) / 1000.0);
    const int n = sensor.rfind("ls-", 0) == 0 ? 1 + pick(5) : 1 + pick(background ? 12 : 25);
    return fmt(a) + ":" + fmt(b) + ":" + std::to_string(n);
  }
  static std::string fmt(double v) {
    char s[32];
    std::snprintf(s, sizeof s, "%.3g", v);
    return s;
  }

  std::string integer_flag(const std::string& flag, int lo, int hi) {
    if (chance(15))
      return " " + flag + " " + one_of<std::string>({"0", "-1", "1e12", "2.5", "x", "99999999999", "1e40"});
    return " " + flag + " " + std::to_string(lo + pick(hi - lo + 1));
  }

  std::string out_flag() {
    const int k = pick(100);
    if (k < 80) return " --out out";
    if (k < 85) return " --out ''";
    if (k < 90) return " --out afile";  // an existing regular file
    if (k < 95) return " --out other";  // holds another command's results
    return " --out other --force";
  }

  std::string budgets() {
    std::string s;
    if (chance(15)) s += one_of<std::string>({" --max-seconds 30", " --max-seconds 0", " --max-seconds x"});
    if (chance(15)) s += one_of<std::string>({" --max-memory 1G", " --max-memory 12Q", " --max-memory 1K"});
    return s;
  }

  std::string sets(const std::string& sensor) {
    if (!chance(20)) return "";
    const std::map<std::string, std::vector<std::string>> keys = {
        {"ls-conventional", {"timing.clock_Hz=50e6", "multisampling.samplings=3", "pixel.columns=99999", "nope=1"}},
        {"ls-demodulation", {"optics.distance_m=1.2", "pixel.rows=0", "nope.key=2"}},
        {"tof-lockin", {"pixel.charge_separation=1.0000001", "source.pulse_width_s=5e-8", "gates.clock_Hz=-1"}},
        {"tof-spad", {"tdc.bits=12", "tdc.bits=0", "laser.repetition_rate_Hz=nan"}}};
    return " --set " + one_of(keys.at(sensor));
  }

  std::string evaluate() {
    const std::string sensor = one_of(kSensors);
    std::string c = "evaluate " + (chance(5) ? one_of<std::string>({"/dev/null", "nodir/", "afile"}) : sensor);
    if (sensor.rfind("ls-", 0) == 0 || chance(60)) c += " --signal " + grid(sensor, false);
    if (sensor.rfind("ls-", 0) == 0 || chance(60)) c += " --background " + grid(sensor, true);
    if (sensor == "ls-conventional" && chance(30)) c += integer_flag("--samplings", 1, 8);
    if (chance(15)) c += integer_flag("--frames", 1, 4);
    if (chance(10)) c += integer_flag("--adc-bits", 1, 12);
    c += sets(sensor);
    if (chance(80)) c += " --no-plots";
    if (chance(20)) c += " --json";
    return c + out_flag() + budgets();
  }

  std::string monte_carlo() {
    const std::string sensor = one_of<std::string>({"ls-conventional", "tof-lockin", "tof-spad"});
    const std::map<std::string, std::string> tiny = {{"ls-conventional", "0.03:0.5:2 --background 0.002:0.01:2"},
                                                     {"tof-lockin", "2e-10:1e-9:2 --background 1e-11:1e-10:2"},
                                                     {"tof-spad", "1e4:1e5:2 --background 1e3:1e4:2"}};
    std::string c =
        "evaluate " + sensor + " --signal " + tiny.at(sensor) + integer_flag("--trials", 2, 6) + " --no-plots";
    if (chance(40)) c += integer_flag("--threads", 1, 2);
    if (chance(30))
      c += " --seed " + one_of<std::string>({"7", "18446744073709551615", "-1", "18446744073709551616", "s"});
    return c + out_flag() + budgets();
  }

  std::string simulate() {
    const std::string sensor = one_of(kSensors);
    const std::map<std::string, std::string> scene = {{"ls-conventional", "plane.toml"},
                                                      {"ls-demodulation", "ls-demodulation-plane.toml"},
                                                      {"tof-lockin", "tof-lockin-plane.toml"},
                                                      {"tof-spad", "tof-spad-plane.toml"}};
    const int k = pick(100);
    const std::string file = k < 75   ? kScenes + "/" + scene.at(sensor)
                             : k < 82 ? kScenes + "/" + scene.at(one_of(kSensors))
                             : k < 88 ? "missing.toml"
                             : k < 94 ? "adir"
                                      : "/dev/zero";
    std::string c = "simulate " + sensor + " --scene " + file;
    const bool systemc = chance(25);
    if (!systemc) c += " --kernel-only";
    if (systemc && chance(30)) c += one_of<std::string>({" --trace t.vcd", " --trace adir", " --trace ''"});
    if (chance(50)) c += integer_flag("--frames", 1, 3);
    if (chance(20)) c += " --seed " + one_of<std::string>({"3", "-1", "18446744073709551616"});
    if (chance(20)) c += " --noise-free";
    c += sets(sensor);
    return c + " --no-plots" + out_flag() + budgets();
  }

  std::string sweep() {
    const std::string sensor = one_of<std::string>({"tof-spad", "tof-lockin"});
    const std::string vary = sensor == "tof-spad"
                                 ? one_of<std::string>({"tdc.bits=10,12", "tdc.bits=0,12", "tdc.bits"})
                                 : one_of<std::string>({"source.pulse_width_s=5e-8,1e-7",
                                                        "source.pulse_width_s=1e-8:1e-7:2:log", "nope=1,2"});
    std::string c = "sweep " + sensor + " --vary " + vary +
                    " --set evaluation.signal_points=3 --set evaluation.background_points=3 --no-plots";
    if (chance(20)) c += one_of<std::string>({" --shard 1/2", " --shard 3/2", " --shard x"});
    return c + out_flag() + budgets();
  }

  std::string frame_rate_or_show() {
    const std::string sensor = chance(90) ? one_of(kSensors) : one_of<std::string>({"adir/p.toml", "/dev/zero", "x"});
    if (chance(50)) return "frame-rate " + sensor + (chance(30) ? integer_flag("--samplings", 1, 8) : "") + " --json";
    return "show " + sensor + sets(one_of(kSensors)) + (chance(50) ? " --json" : "");
  }

  std::string merge() {
    return "merge" + out_flag() + " " + one_of<std::string>({"missing.json", "afile", "adir", "/dev/null"});
  }

  std::string cosim_flags() {
    return "cosim tdc" + one_of<std::string>({" --cycles -5", " --cycles 1e10", " --seed -1", " --cycles x",
                                              " --junit adir", " --junit ''"});
  }
};

// Every path under `dir`, relative, with the file contents' size (a snapshot to compare).
std::map<std::string, std::uintmax_t> snapshot(const fs::path& dir) {
  std::map<std::string, std::uintmax_t> s;
  std::error_code ec;
  for (auto it = fs::recursive_directory_iterator(dir, ec); it != fs::recursive_directory_iterator();
       it.increment(ec)) {
    const auto& e = *it;
    s[fs::relative(e.path(), dir).string()] = e.is_regular_file(ec) ? e.file_size(ec) : 0;
  }
  return s;
}

// The fixture every command meets: a regular file, a folder, and a folder with another command's
// results (a table's).
void prepare(const fs::path& work) {
  fs::remove_all(work);
  fs::create_directories(work / "adir");
  std::ofstream(work / "afile") << "not a folder\n";
  fs::create_directories(work / "other");
  std::ofstream(work / "other" / ".rangesim-manifest") << "rangesim-output 1\nkind table\nfile table5_1.md\n";
  std::ofstream(work / "other" / "table5_1.md") << "| a table |\n";
}

std::uint64_t env_or(const char* name, std::uint64_t fallback) {
  const char* v = std::getenv(name);
  return v && *v ? std::strtoull(v, nullptr, 10) : fallback;
}

TEST(Soak, RandomCommandLinesEndCleanlyWithinTheirBounds) {
  const std::uint64_t seed = env_or("SOAK_SEED", RANGESIM_SOAK_SEED);
  const std::uint64_t count = env_or("SOAK_COUNT", RANGESIM_SOAK_COUNT);
  char tmpl[] = "/tmp/rangesim-soak-XXXXXX";
  const fs::path root = ::mkdtemp(tmpl), work = root / "work";
  Generator gen(seed);
  std::map<int, int> codes;
  double slowest = 0;
  long largest = 0;
  for (std::uint64_t i = 0; i < count; ++i) {
    const std::string args = gen.command();
    SCOPED_TRACE("SOAK_SEED=" + std::to_string(seed) + " command " + std::to_string(i) + ": rangesim " + args);
    prepare(work);
    const auto before = snapshot(work);
    std::vector<std::string> argv = split_args(args);
    argv.insert(argv.begin(), kBin);
    const ChildResult r = run_child(argv, work.string(), {kWallLimitS, kAddressSpace});
    ++codes[r.signal ? 128 + r.signal : r.exit_code];
    slowest = std::max(slowest, r.wall_s), largest = std::max(largest, r.max_rss_kib);
    EXPECT_FALSE(r.timed_out) << "still running after " << kWallLimitS << " s";
    EXPECT_EQ(r.signal, 0) << "ended by signal " << r.signal << "\n" << r.err;
    const std::set<int> documented = {0, 2, 3, 4};
    EXPECT_TRUE(documented.count(r.exit_code)) << "exit " << r.exit_code << "\n" << r.err;
    EXPECT_LE(r.max_rss_kib, kMaxRssKib);
    if (r.exit_code == 2) {
      EXPECT_TRUE(r.out.empty()) << r.out;
    }
    const auto after = snapshot(work);
    for (const auto& [path, size] : after) {
      const std::string name = fs::path(path).filename().string();
      EXPECT_EQ(name.rfind(".staging-", 0) == 0 && name != ".staging-sweep", false) << "left behind: " << path;
      EXPECT_NE(name, ".rangesim.lock") << "left behind: " << path;
      EXPECT_EQ(name.find(".partial-"), std::string::npos) << "left behind: " << path;
      // A failed run changes nothing (a budget's journal excepted, which says how to resume).
      if (r.exit_code != 0 && path.find(".staging-sweep") == std::string::npos) {
        EXPECT_TRUE(before.count(path) && before.at(path) == size) << "written by a failed run: " << path;
      }
    }
    for (const auto& [path, size] : before)
      if (r.exit_code != 0) {
        EXPECT_TRUE(after.count(path)) << "removed by a failed run: " << path;
      }
    if (::testing::Test::HasFailure()) break;
  }
  std::string summary;
  for (const auto& [code, n] : codes) summary += " exit " + std::to_string(code) + ": " + std::to_string(n) + ";";
  std::printf("soak: seed %llu, %llu command lines;%s slowest %.1f s, largest %ld KiB resident\n",
              static_cast<unsigned long long>(seed), static_cast<unsigned long long>(count), summary.c_str(), slowest,
              largest);
  fs::remove_all(root);
}

}  // namespace
