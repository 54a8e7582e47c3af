// The ls-conventional sensor under SystemC (elaborates: one test per process): outputs identical
// to the bare kernel on the same stimulus, bounded runs with zero SC errors, simulated time equal
// to cycles / clock, and a VCD trace read back and checked against the kernel's results.
#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <string>
#include <unistd.h>

#include "tests/systemc/elaboration_guard.h"
#include "golden/ls_conventional/frame_timing.h"
#include "tests/systemc/sensor_test_helpers.h"
#include "systemc/ls_conventional/sensor.h"
#include "tests/systemc/vcd_reader.h"

namespace rs = rangesim::systemc;
using rangesim::LsConventionalConfig;
using rs::test::RandomStimulus;
using rs::test::small_config;

namespace {

rs::SensorKernelOptions noisy(bool skip) {
  rs::SensorKernelOptions o;
  o.event_skipping = skip;
  o.pixel.seed = 9;
  return o;
}

}  // namespace

TEST(LsConventionalSensorModule, OutputsEqualTheBareKernelOnTheSameStimulus) {
  REQUIRE_FRESH_ELABORATION();
  const LsConventionalConfig c = small_config(16, 96, 4);
  rs::SensorRunOptions run;
  run.frames = 6;
  const rs::SensorRunResult sc = rs::run_sensor_systemc(c, noisy(false), RandomStimulus{}, run);
  const rs::SensorRunResult ticked = rs::run_sensor_kernel(c, noisy(false), RandomStimulus{}, run);
  const rs::SensorRunResult skipped = rs::run_sensor_kernel(c, noisy(true), RandomStimulus{}, run);
  ASSERT_EQ(sc.frames.size(), 6U);
  ASSERT_EQ(ticked.frames.size(), 6U);
  int detected = 0;
  for (std::size_t f = 0; f < sc.frames.size(); ++f) {
    EXPECT_TRUE(sc.frames[f] == ticked.frames[f]) << "frame " << f;
    EXPECT_TRUE(sc.frames[f] == skipped.frames[f]) << "frame " << f;
    detected += sc.frames[f].rows_detected();
  }
  EXPECT_GT(detected, 0);
  EXPECT_EQ(sc.cycles, ticked.cycles);
  const long long F = rangesim::golden::frame_timing(c.timing, 4).frame_cycles;
  EXPECT_EQ(sc.cycles, 6 * F);
  // Simulated time from sc_time_stamp: cycles / clock (1 fs resolution: < 1e-7 relative).
  EXPECT_NEAR(sc.simulated_time_s, sc.cycles / c.timing.clock_Hz, 1e-7 * sc.simulated_time_s);
  EXPECT_EQ(sc.sc_errors, 0);
  EXPECT_EQ(sc.sc_warnings, 0);
  EXPECT_EQ(sc_core::sc_report_handler::get_count(sc_core::SC_ERROR), 0);
}

TEST(LsConventionalSensorModule, FullPresetArrayOneFrameEqualsKernel) {
  REQUIRE_FRESH_ELABORATION();
  LsConventionalConfig c;  // 375 x 365, four samplings
  c.pixel.read_noise_V = 0.3e-3;
  RandomStimulus stim;
  stim.columns = c.pixel.columns;
  rs::SensorRunOptions run;
  run.frames = 2;
  const rs::SensorRunResult sc = rs::run_sensor_systemc(c, noisy(false), stim, run);
  const rs::SensorRunResult k = rs::run_sensor_kernel(c, noisy(true), stim, run);
  ASSERT_EQ(sc.frames.size(), 2U);
  for (std::size_t f = 0; f < 2; ++f) EXPECT_TRUE(sc.frames[f] == k.frames[f]) << f;
  EXPECT_EQ(sc.frames[0].cycles, 100);
  EXPECT_EQ(sc.sc_errors, 0);
}

TEST(LsConventionalSensorModule, CycleBudgetBoundsTheRun) {
  REQUIRE_FRESH_ELABORATION();
  rs::SensorRunOptions run;
  run.frames = 3;
  run.cycle_budget = 250;  // 2.5 frame accesses
  EXPECT_THROW(rs::run_sensor_systemc(small_config(), noisy(false), RandomStimulus{}, run), std::runtime_error);
  EXPECT_EQ(sc_core::sc_report_handler::get_count(sc_core::SC_ERROR), 0);
}

TEST(LsConventionalSensorModule, TraceIsWrittenAndReadsBack) {
  REQUIRE_FRESH_ELABORATION();
  const LsConventionalConfig c = small_config(8, 96, 4);
  const std::string dir =
      (std::filesystem::temp_directory_path() / ("rangesim-trace-" + std::to_string(::getpid()))).string();
  std::filesystem::create_directories(dir);
  rs::SensorRunOptions run;
  run.frames = 3;
  run.vcd_base = dir + "/sensor";
  run.traced_rows = {0, 3, 7};
  const rs::SensorRunResult sc = rs::run_sensor_systemc(c, noisy(false), RandomStimulus{}, run);
  ASSERT_EQ(sc.frames.size(), 3U);
  EXPECT_EQ(sc.sc_errors, 0);

  const rs::test::VcdFile vcd = rs::test::read_vcd(dir + "/sensor.vcd");
  ASSERT_TRUE(vcd.ok) << vcd.error;
  EXPECT_EQ(vcd.timescale, "1 fs");
  // Scopes follow the block tree (systemc/common/waveform.h).
  const std::string top = "ls_conventional.", seq = top + "sequencer.";
  for (const std::string& name : {top + "clk", top + "rst", seq + "pix_reset", seq + "latch", seq + "search_start",
                                 seq + "frame_done", seq + "phase", seq + "sampling", seq + "frame",
                                 top + "row3.address_search.addr_valid", top + "row3.address_search.addr_bit",
                                 top + "row3.centre_processor.centre_q", top + "row7.centre_processor.valid"})
    EXPECT_TRUE(vcd.has(name)) << name;
  // GTKWave opens it grouped by block, with the sequencer's phases by name.
  std::ifstream gtkw(dir + "/sensor.gtkw");
  const std::string save((std::istreambuf_iterator<char>(gtkw)), std::istreambuf_iterator<char>());
  EXPECT_NE(save.find("[dumpfile] \"sensor.vcd\""), std::string::npos);
  EXPECT_NE(save.find("-ls_conventional.row3.centre_processor"), std::string::npos);
  EXPECT_NE(
      save.find("^1 sensor.ls_conventional.sequencer.phase.txt\n@2024\nSystemC.ls_conventional.sequencer.phase[31:0]"),
      std::string::npos)
      << save;
  std::ifstream names(dir + "/sensor.ls_conventional.sequencer.phase.txt");
  const std::string phases((std::istreambuf_iterator<char>(names)), std::istreambuf_iterator<char>());
  EXPECT_NE(phases.find("1 latch\n"), std::string::npos) << phases;
  // Sample every cycle at its opening clock edge (values written at an edge belong to the cycle it opens).
  const std::vector<std::uint64_t> edges = vcd.rising_edges(top + "clk");
  const long long F = rangesim::golden::frame_timing(c.timing, 4).frame_cycles;
  ASSERT_GE(static_cast<long long>(edges.size()), 1 + 3 * F);  // two reset edges; the stopping edge is not dumped
  long long latch_cycles = 0, frames_done = 0;
  const int B = c.timing.address_bits;
  for (int row : run.traced_rows) {
    const std::string p = top + "row" + std::to_string(row) + ".";
    std::uint64_t shift = 0, sum = 0;
    int bits = 0, count = 0;
    long long frame = 0;
    for (std::size_t e = 0; e < edges.size() && frame < 3; ++e) {
      const std::uint64_t t = edges[e];
      if (vcd.sample(top + "rst", t)) continue;
      if (row == run.traced_rows.front()) latch_cycles += vcd.sample(seq + "latch", t);
      if (vcd.sample(p + "address_search.addr_valid", t)) {
        shift = (shift << 1) | vcd.sample(p + "address_search.addr_bit", t);
        if (++bits == 2 * B) {
          sum += (shift >> B) + (shift & ((1U << B) - 1));
          ++count;
          shift = 0;
          bits = 0;
        }
      }
      if (vcd.sample(seq + "frame_done", t)) {
        const rs::CentreProcessorPins& k =
            sc.frames[static_cast<std::size_t>(frame)].rows[static_cast<std::size_t>(row)];
        EXPECT_EQ(sum, k.sum) << "row " << row << " frame " << frame;
        EXPECT_EQ(count, k.count) << "row " << row << " frame " << frame;
        EXPECT_EQ(vcd.sample(p + "centre_processor.centre_q", t), k.centre_q) << "row " << row << " frame " << frame;
        EXPECT_EQ(vcd.sample(seq + "frame", t), static_cast<std::uint64_t>(frame));
        if (row == run.traced_rows.front()) ++frames_done;
        sum = 0;
        count = 0;
        ++frame;
      }
    }
    EXPECT_EQ(frame, 3) << "row " << row;
  }
  EXPECT_EQ(frames_done, 3);
  EXPECT_EQ(latch_cycles, 3 * 4 * c.timing.latch_cycles);
  if (!HasFailure()) std::filesystem::remove_all(dir);
}
