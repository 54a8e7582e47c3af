// End-to-end through the rangesim binary, for every sensor: depth-map scenes (ground truth = the
// map, range error small) and --trace FILE.fst read back with fst2vcd from the gtkwave package
// (named signals present, values that move).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "run_command.h"
#include "vcd_reader.h"

namespace fs = std::filesystem;
using rangesim::systemc::test::read_vcd;
using rangesim::systemc::test::VcdFile;

namespace {

const std::string kDriver = SIMULATE_DRIVER_BIN;
const std::string kScenes = RANGESIM_SCENE_DIR;

CommandResult rangesim_cmd(const std::string& args) {
  return run_command("SYSTEMC_DISABLE_COPYRIGHT_MESSAGE=1 " + kDriver + " " + args);
}

// Column `name` of a CSV file as numbers (empty cells skipped).
std::vector<double> csv_column(const std::string& path, const std::string& name) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  std::vector<std::string> head;
  std::stringstream hs(line);
  for (std::string h; std::getline(hs, h, ',');) head.push_back(h);
  const auto idx = static_cast<std::size_t>(std::find(head.begin(), head.end(), name) - head.begin());
  std::vector<double> v;
  while (std::getline(in, line)) {
    std::stringstream ls(line);
    std::string cell;
    for (std::size_t i = 0; std::getline(ls, cell, ','); ++i)
      if (i == idx && !cell.empty()) v.push_back(std::stod(cell));
  }
  return v;
}

struct DepthCase {
  const char* sensor;
  const char* scene;
  const char* args;      // frames, harness
  double rms_max_m;      // bound on the range error against the map
  double near_m, far_m;  // the scene's depth_near_m / depth_far_m
  bool has_points;       // writes points.csv with truth_range_m
  double min_span;       // the truth must span this fraction of [near, far] (the map is not flat there)
};

}  // namespace

TEST(SimulateDepthMap, EverySensorRangesTheMap) {
  const DepthCase cases[] = {
      {"ls-conventional", "depth-map", "--frames 60 --kernel-only", 5e-3, 0.95, 1.15, true, 0.3},
      {"ls-demodulation", "ls-demodulation-depth-map", "--frames 3 --kernel-only", 5e-3, 0.98, 1.06, true,
       0.01},  // 3 frames: the stripe at the map's edge
      {"tof-lockin", "tof-lockin-depth-map", "--kernel-only --noise-free", 20e-3, 2.0, 4.0, false, 0},
      {"tof-spad", "tof-spad-depth-map", "--kernel-only", 15e-3, 1.5, 3.0, true, 0.3},
  };
  const std::string dir = make_temp_dir();
  for (const DepthCase& c : cases) {
    const std::string out = dir + "/" + c.sensor;
    const CommandResult r = rangesim_cmd(std::string("simulate ") + c.sensor + " --scene " + kScenes + "/" + c.scene +
                                         ".toml " + c.args + " --json --no-plots --csv --points --out " + out);
    ASSERT_EQ(r.exit_code, 0) << c.sensor << "\n" << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["target_shape"], "depth_map") << c.sensor;
    EXPECT_TRUE(j["timing_matches_golden"].get<bool>()) << c.sensor;
    EXPECT_GT(j["points_detected"].get<long long>(), 0) << c.sensor;
    EXPECT_LT(j["range_error_rms_m"].get<double>(), c.rms_max_m) << c.sensor;
    if (!c.has_points) continue;
    // The ground truth comes from the map: inside [near, far] and spanning a good part of it.
    const auto truth = csv_column(out + "/points.csv", "truth_range_m");
    ASSERT_FALSE(truth.empty()) << c.sensor;
    const auto [lo, hi] = std::minmax_element(truth.begin(), truth.end());
    EXPECT_GE(*lo, c.near_m - 1e-9) << c.sensor;
    EXPECT_LE(*hi, c.far_m + 1e-9) << c.sensor;
    EXPECT_GT(*hi - *lo, c.min_span * (c.far_m - c.near_m)) << c.sensor;
  }
  fs::remove_all(dir);
}

TEST(SimulateDepthMap, BadDepthMapExitsTwoNamingFileAndKey) {
  const std::string dir = make_temp_dir();
  std::ofstream(dir + "/s.toml")
      << "[scene]\nname = \"s\"\n[target]\nshape = \"depth_map\"\ndepth_map_file = \"nope.pgm\"\n"
         "depth_near_m = 1\ndepth_far_m = 2\n[rates]\nsignal_Hz = 1e4\n";
  const CommandResult r =
      rangesim_cmd("simulate tof-spad --scene " + dir + "/s.toml --kernel-only --out " + dir + "/o");
  EXPECT_EQ(r.exit_code, 2) << r.err;
  EXPECT_NE(r.err.find(dir + "/s.toml:5: target.depth_map_file (" + dir + "/nope.pgm): cannot read"), std::string::npos)
      << r.err;
  EXPECT_FALSE(fs::exists(dir + "/o"));
  std::ofstream(dir + "/far.pgm") << "P2 1 1 1 1\n";
  std::ofstream(dir + "/t.toml")
      << "[scene]\nname = \"t\"\n[target]\nshape = \"depth_map\"\ndepth_map_file = \"far.pgm\"\n"
         "depth_near_m = 1\ndepth_far_m = 0.1\n[rates]\nsignal_Hz = 1e4\n";
  const CommandResult f =
      rangesim_cmd("simulate tof-spad --scene " + dir + "/t.toml --kernel-only --out " + dir + "/o");
  EXPECT_EQ(f.exit_code, 2) << f.err;
  // Nearer than 0.3 m is refused (beyond the unambiguous range the echo is aliased, with a note).
  EXPECT_NE(f.err.find("target.depth_map_file: distance 0.1 m; allowed 0.3 m <= distance"), std::string::npos) << f.err;
  EXPECT_FALSE(fs::exists(dir + "/o"));
  fs::remove_all(dir);
}

namespace {

struct TraceCase {
  const char* sensor;
  const char* scene;
  const char* args;
  std::vector<std::string> signals;  // must be in the waveform
  const char* moving;                // a signal that must change at least `changes` times
  std::size_t changes;
};

// Test names and messages show the sensor, not the struct's bytes.
void PrintTo(const TraceCase& c, std::ostream* os) { *os << c.sensor; }

// fst2vcd the FST and read it back.
VcdFile fst_to_vcd(const std::string& fst, const std::string& vcd) {
  const CommandResult c = run_command("fst2vcd -f " + fst + " -o " + vcd);
  EXPECT_EQ(c.exit_code, 0) << c.err;
  return read_vcd(vcd);
}

}  // namespace

class SimulateTraceFst : public ::testing::TestWithParam<TraceCase> {};

TEST_P(SimulateTraceFst, ReadBackByFst2Vcd) {
  const TraceCase& c = GetParam();
  const std::string dir = make_temp_dir();
  const CommandResult r =
      rangesim_cmd(std::string("simulate ") + c.sensor + " --scene " + kScenes + "/" + c.scene + ".toml " + c.args +
                   " --json --no-plots --trace " + dir + "/w.fst --out " + dir + "/o");
  ASSERT_EQ(r.exit_code, 0) << r.err;
  // Every edge is representable in the trace's time unit: no SystemC warning per edge.
  EXPECT_EQ(r.err.find("W713"), std::string::npos) << r.err.substr(0, 2000);
  EXPECT_EQ(nlohmann::json::parse(r.out)["trace"], dir + "/w.fst");
  ASSERT_TRUE(fs::exists(dir + "/w.fst"));
  for (const auto& e : fs::directory_iterator(dir))  // no temporary VCD or FST left behind
    EXPECT_EQ(e.path().string().find(".partial"), std::string::npos) << e.path();
  std::ifstream fst(dir + "/w.fst", std::ios::binary);
  std::string head(5, '\0');
  fst.read(&head[0], 5);
  EXPECT_EQ(head.find("$"), std::string::npos) << "an FST is binary, not VCD text";
  const VcdFile v = fst_to_vcd(dir + "/w.fst", dir + "/w.vcd");
  ASSERT_TRUE(v.ok) << v.error;
  for (const auto& s : c.signals) EXPECT_TRUE(v.has(s)) << s;
  ASSERT_TRUE(v.has(c.moving));
  EXPECT_GE(v.of(c.moving).size(), c.changes) << c.moving;
  EXPECT_GT(v.end_time, 0U);
  fs::remove_all(dir);
}

INSTANTIATE_TEST_SUITE_P(
    EverySensor, SimulateTraceFst,
    ::testing::Values(TraceCase{"ls-conventional",
                                "plane",
                                "--frames 2",
                                {"ls_conventional.clk", "ls_conventional.rst", "ls_conventional.sequencer.latch",
                                 "ls_conventional.sequencer.search_start",
                                 "ls_conventional.row0.address_search.addr_bit", "ls_conventional.sequencer.frame"},
                                "ls_conventional.sequencer.latch",
                                8},
                      TraceCase{"ls-demodulation",
                                "ls-demodulation-plane",
                                "--frames 1 --tick",
                                {"ls_demodulation.clk", "ls_demodulation.sequencer.phase",
                                 "ls_demodulation.sequencer.decision", "ls_demodulation.sequencer.phase_cycle",
                                 "ls_demodulation.sequencer.mpy_plus", "ls_demodulation.readout.row",
                                 "ls_demodulation.readout.search_start", "ls_demodulation.readout.addr_valid",
                                 "ls_demodulation.readout.addr_bit", "ls_demodulation.sequencer.frame_done"},
                                "ls_demodulation.readout.addr_valid",
                                1},
                      TraceCase{"tof-lockin",
                                "tof-lockin-plane",
                                "--frames 1",
                                {"tof_lockin.gates.tx1", "tof_lockin.gates.tx2", "tof_lockin.gates.txd",
                                 "tof_lockin.gates.light", "tof_lockin.sequencer.phase", "tof_lockin.sequencer.row"},
                                "tof_lockin.sequencer.row",
                                100},  // gates aggregated: rows move
                      TraceCase{"tof-spad",
                                "tof-spad-plane",
                                "--frames 1",
                                {"tof_spad.sequencer.row", "tof_spad.sequencer.phase", "tof_spad.histogram.word_valid",
                                 "tof_spad.histogram.word"},
                                "tof_spad.histogram.word_valid",
                                1}),
    [](const ::testing::TestParamInfo<TraceCase>& i) {
      std::string n = i.param.sensor;
      std::replace(n.begin(), n.end(), '-', '_');
      return n;
    });

TEST(SimulateTrace, LsDemodulationVcdEqualsFstAndBadTraceNamesWriteNothing) {
  const std::string dir = make_temp_dir();
  // --no-aggregate: the periods stepped one by one, so the trace shows every MPY edge (aggregated,
  // the integration is one jump and mpy_plus shows none of them).
  const std::string base = "simulate ls-demodulation --scene " + kScenes +
                           "/ls-demodulation-plane.toml --frames 1 --json --no-plots --no-aggregate";
  const CommandResult a = rangesim_cmd(base + " --trace " + dir + "/a.vcd --out " + dir + "/a");
  const CommandResult b = rangesim_cmd(base + " --trace " + dir + "/b.fst --out " + dir + "/b");
  ASSERT_EQ(a.exit_code, 0) << a.err;
  ASSERT_EQ(b.exit_code, 0) << b.err;
  const VcdFile va = read_vcd(dir + "/a.vcd"), vb = fst_to_vcd(dir + "/b.fst", dir + "/b.vcd");
  ASSERT_TRUE(va.ok && vb.ok) << va.error << vb.error;
  for (const char* s :
       {"ls_demodulation.sequencer.mpy_plus", "ls_demodulation.sequencer.frame_done",
        "ls_demodulation.readout.row_valid", "ls_demodulation.readout.row", "ls_demodulation.sequencer.decision"}) {
    ASSERT_TRUE(va.has(s) && vb.has(s)) << s;
    EXPECT_EQ(va.of(s), vb.of(s)) << s;  // the conversion keeps every change
  }
  // Each trace comes with its GTKWave save file, naming the dump it opens, and the phase names.
  for (const auto& [stem, dump] : {std::pair{"a", "a.vcd"}, std::pair{"b", "b.fst"}}) {
    std::ifstream g(dir + "/" + stem + ".gtkw");
    const std::string save((std::istreambuf_iterator<char>(g)), std::istreambuf_iterator<char>());
    EXPECT_NE(save.find(std::string("[dumpfile] \"") + dump + "\""), std::string::npos) << save;
    EXPECT_TRUE(fs::exists(dir + "/" + stem + ".ls_demodulation.sequencer.phase.txt")) << stem;
  }
  // The trace's folder is made.
  const CommandResult c = rangesim_cmd(base + " --trace " + dir + "/new/sub/c.vcd --out " + dir + "/c");
  EXPECT_EQ(c.exit_code, 0) << c.err;
  EXPECT_TRUE(fs::exists(dir + "/new/sub/c.vcd") && fs::exists(dir + "/new/sub/c.gtkw"));
  EXPECT_GE(va.rising_edges("ls_demodulation.sequencer.mpy_plus").size(),
            4U);  // N = 5 correlation periods; event skipping shows the edges it stops at
  // Bad --trace: exit 2, the message names the flag, nothing written.
  struct Case {
    std::string args, message;
  };
  const Case cases[] = {{" --trace " + dir + "/w.txt", "must end in .vcd or .fst"},
                        {" --trace " + dir + "/w.fst --kernel-only", "--trace needs the SystemC model"},
                        {" --trace " + dir + "/folder.vcd", "exists and is a directory"}};
  fs::create_directories(dir + "/folder.vcd");
  for (const Case& c : cases) {
    const CommandResult r = rangesim_cmd(base + c.args + " --out " + dir + "/o");
    EXPECT_EQ(r.exit_code, 2) << c.args << "\n" << r.err;
    EXPECT_NE(r.err.find(c.message), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir + "/o")) << c.args;
    EXPECT_FALSE(fs::exists(dir + "/w.fst")) << c.args;
  }
  fs::remove_all(dir);
}

TEST(SimulatePresetKeys, TofSpadReadoutWordRateSetsTheReadoutPhaseInGoldenAndKernel) {
  const std::string dir = make_temp_dir();
  std::ifstream in(std::string(RANGESIM_SOURCE_DIR) + "/presets/tof-spad.toml");
  std::stringstream ss;
  ss << in.rdbuf();
  std::string text = ss.str();
  const std::string key = "readout_word_rate_Hz = { value = 100e6,";
  ASSERT_NE(text.find(key), std::string::npos);
  text.replace(text.find(key), key.size(), "readout_word_rate_Hz = { value = 50e6,");
  std::ofstream(dir + "/slow.toml") << text;
  auto readout_cycles = [](const nlohmann::json& phases) {
    for (const auto& p : phases)
      if (p["name"] == "histogram_readout")
        return p.contains("golden_cycles") ? p["golden_cycles"].get<long long>() : p["cycles"].get<long long>();
    return -1LL;
  };
  const CommandResult fast = rangesim_cmd("frame-rate tof-spad --json"),
                      slow = rangesim_cmd("frame-rate " + dir + "/slow.toml --json");
  ASSERT_EQ(fast.exit_code, 0) << fast.err;
  ASSERT_EQ(slow.exit_code, 0) << slow.err;
  const long long rf = readout_cycles(nlohmann::json::parse(fast.out)["phases"]);
  const long long rs = readout_cycles(nlohmann::json::parse(slow.out)["phases"]);
  // W = ceil(clock / word rate): 103 cycles per word at 100 MHz, 205 at 50 MHz (clock 10.24 GHz).
  EXPECT_GT(rf, 0);
  EXPECT_NEAR(static_cast<double>(rs) / static_cast<double>(rf), 2.0, 0.02);
  const CommandResult sim = rangesim_cmd("simulate " + dir + "/slow.toml --scene " + kScenes +
                                         "/tof-spad-plane.toml --kernel-only --json --no-plots --out " + dir + "/o");
  ASSERT_EQ(sim.exit_code, 0) << sim.err;
  const auto j = nlohmann::json::parse(sim.out);
  EXPECT_TRUE(j["timing_matches_golden"].get<bool>());
  for (const auto& p : j["phases"]) {
    if (p["name"] == "histogram_readout") {
      EXPECT_EQ(p["cycles"].get<long long>(), rs);
    }
  }
  fs::remove_all(dir);
}

// --trace-rows chooses the rows whose blocks the ls-conventional waveform shows; a row outside the
// array is refused naming the range, and a sensor without per-row blocks refuses the flag.
TEST(SimulateTrace, TraceRowsChooseTheRowsShown) {
  const std::string dir = make_temp_dir();
  const std::string base = "simulate ls-conventional --scene " + kScenes + "/plane.toml --frames 2 --json --no-plots";
  const CommandResult ok = rangesim_cmd(base + " --trace " + dir + "/r.vcd --trace-rows 3,100 --out " + dir + "/o");
  ASSERT_EQ(ok.exit_code, 0) << ok.err;
  const VcdFile v = read_vcd(dir + "/r.vcd");
  ASSERT_TRUE(v.ok) << v.error;
  EXPECT_TRUE(v.has("ls_conventional.row3.address_search.addr_valid"));
  EXPECT_TRUE(v.has("ls_conventional.row100.centre_processor.centre_q"));
  EXPECT_FALSE(v.has("ls_conventional.row0.centre_processor.centre_q"));
  const CommandResult bad = rangesim_cmd(base + " --trace " + dir + "/b.vcd --trace-rows 365 --out " + dir + "/b");
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("--trace-rows 365: allowed 0..364"), std::string::npos) << bad.err;
  EXPECT_FALSE(fs::exists(dir + "/b.vcd") || fs::exists(dir + "/b"));
  const CommandResult spad = rangesim_cmd("simulate tof-spad --scene " + kScenes + "/tof-spad-plane.toml --trace " +
                                          dir + "/s.vcd --trace-rows 1 --out " + dir + "/s");
  EXPECT_EQ(spad.exit_code, 2);
  EXPECT_NE(spad.err.find("allowed with ls-conventional"), std::string::npos) << spad.err;
  fs::remove_all(dir);
}

// --trace-pixels: each sensor shows the chosen pixels' own signals; the tof-spad trace shows every
// timed avalanche of the pixel's TDC group with its code and the histogram write it caused; a
// traced run gives the untraced run's range map; a pixel outside the window is refused naming it
// and leaves nothing behind.
TEST(SimulateTrace, TracePixelsShowEachSensorsPixelSignals) {
  const std::string dir = make_temp_dir();
  struct Case {
    const char *sensor, *scene, *pixel;
    std::vector<std::string> signals;
  };
  const std::vector<Case> cases = {
      {"ls-conventional", "plane.toml", "182:187", {"ls_conventional.pixel_182_187.active"}},
      {"ls-demodulation",
       "ls-demodulation-plane.toml",
       "5:2",
       {"ls_demodulation.pixel_5_2.out_plus_V", "ls_demodulation.pixel_5_2.active"}},
      {"tof-lockin",
       "tof-lockin-step.toml",
       "5:7",
       {"tof_lockin.pixel_5_7.adc_code1", "tof_lockin.pixel_5_7.fd2_e", "tof_lockin.column_adc_7.code2",
        "tof_lockin.sequencer.gate_cycles"}},
      {"tof-spad",
       "tof-spad-step.toml",
       "64:65",
       {"tof_spad.tdc_16.hit", "tof_spad.tdc_16.code", "tof_spad.tdc_16.result", "tof_spad.pixel_64_65.avalanche",
        "tof_spad.histogram.write_count", "tof_spad.sequencer.laser_cycle"}},
  };
  for (const Case& c : cases) {
    const std::string base = std::string("simulate ") + c.sensor + " --scene " + kScenes + "/" + c.scene +
                             " --frames 2 --json --no-plots --out " + dir + "/" + c.sensor;
    const CommandResult r = rangesim_cmd(base + " --trace " + dir + "/" + c.sensor + ".vcd --trace-pixels " + c.pixel);
    ASSERT_EQ(r.exit_code, 0) << c.sensor << ": " << r.err;
    const VcdFile v = read_vcd(dir + "/" + c.sensor + ".vcd");
    ASSERT_TRUE(v.ok) << v.error;
    for (const std::string& s : c.signals) EXPECT_TRUE(v.has(s)) << c.sensor << ": " << s;
  }
  // ls-demodulation: pixel (5, 2) is on the stripe of frame 0: its comparator output rises.
  const VcdFile dm = read_vcd(dir + "/ls-demodulation.vcd");
  ASSERT_TRUE(dm.ok) << dm.error;
  EXPECT_FALSE(dm.rising_edges("ls_demodulation.pixel_5_2.active").empty());
  // tof-lockin: the pixel's codes are its column ADC's codes of its row (written at its row).
  const VcdFile lk = read_vcd(dir + "/tof-lockin.vcd");
  ASSERT_TRUE(lk.ok) << lk.error;
  const auto& code = lk.of("tof_lockin.pixel_5_7.adc_code1");
  ASSERT_GE(code.size(), 2u);
  for (std::size_t i = 1; i < code.size(); ++i)
    EXPECT_EQ(code[i].second, lk.sample("tof_lockin.column_adc_7.code1", code[i].first));
  EXPECT_GT(lk.of("tof_lockin.column_adc_7.code1").size(), 10u);  // one per converted row

  // tof-spad: every write is an event of the hit at the same instant, with the hit's code, and the
  // bin's counts rise by one per write.
  const VcdFile sp = read_vcd(dir + "/tof-spad.vcd");
  ASSERT_TRUE(sp.ok) << sp.error;
  const std::vector<std::uint64_t> writes = sp.rising_edges("tof_spad.histogram.write");
  ASSERT_GT(writes.size(), 10u);
  for (std::uint64_t t : writes) {
    EXPECT_EQ(sp.sample("tof_spad.tdc_16.result", t), 1u);
    EXPECT_EQ(sp.sample("tof_spad.tdc_16.code", t), sp.sample("tof_spad.histogram.write_code", t));
    EXPECT_EQ(sp.sample("tof_spad.tdc_16.hit_column", t), sp.sample("tof_spad.histogram.write_column", t));
  }
  EXPECT_FALSE(sp.rising_edges("tof_spad.pixel_64_65.avalanche").empty());
  const CommandResult plain =
      rangesim_cmd(std::string("simulate tof-spad --scene ") + kScenes +
                   "/tof-spad-step.toml --frames 2 --json --no-plots --csv --out " + dir + "/plain");
  const CommandResult traced = rangesim_cmd(std::string("simulate tof-spad --scene ") + kScenes +
                                            "/tof-spad-step.toml --frames 2 --json --no-plots --csv --out " + dir +
                                            "/traced --trace " + dir + "/t2.vcd --trace-pixels 64:65");
  ASSERT_EQ(traced.exit_code, 0) << traced.err;
  std::ifstream a(dir + "/plain/range_map.csv"), b(dir + "/traced/range_map.csv");
  EXPECT_EQ(std::string(std::istreambuf_iterator<char>(a), {}), std::string(std::istreambuf_iterator<char>(b), {}));

  const std::string lockin = "simulate tof-lockin --scene " + kScenes + "/tof-lockin-step.toml --out " + dir + "/bad";
  const CommandResult outside = rangesim_cmd(lockin + " --trace " + dir + "/new/b.vcd --trace-pixels 300:7");
  EXPECT_EQ(outside.exit_code, 2);
  EXPECT_NE(outside.err.find("--trace-pixels 300:7: allowed rows 0..251, columns 0..335"), std::string::npos)
      << outside.err;
  EXPECT_FALSE(fs::exists(dir + "/new") || fs::exists(dir + "/bad"));
  const CommandResult malformed = rangesim_cmd(lockin + " --trace " + dir + "/b.vcd --trace-pixels 3-7");
  EXPECT_EQ(malformed.exit_code, 2);
  EXPECT_NE(malformed.err.find("is not ROW:COLUMN"), std::string::npos) << malformed.err;
  const CommandResult untraced = rangesim_cmd(lockin + " --trace-pixels 3:7");
  EXPECT_EQ(untraced.exit_code, 2);
  EXPECT_NE(untraced.err.find("add --trace"), std::string::npos) << untraced.err;
  fs::remove_all(dir);
}
