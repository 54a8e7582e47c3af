// Co-simulation of the ls-conventional readout RTL (small instance) against the clock-level
// model and golden, and of its blocks; each test runs in its own process (one elaboration).
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <set>
#include <string>

#include "tb/ls_conventional/block_cosim.h"
#include "tb/common/cosim_coverage.h"
#include "tb/common/cosim_target.h"
#include "tb/ls_conventional/cosim.h"

namespace rangesim::tb {
namespace {

int count_check(const CosimReport& r, const std::string& check) {
  int n = 0;
  for (const auto& m : r.first_mismatches) n += m.check == check;
  return n;
}

TEST(LsConventionalCosim, NoiseFreeMatchesModelAndGolden) {
  LsConventionalCosimOptions o;
  o.frames = 60;
  o.seed = 1;  // odd: noise-free, so golden is exact
  const auto res = run_ls_conventional_cosim(o);
  const CosimReport& r = res.report;
  EXPECT_EQ(res.frames, 60);
  EXPECT_EQ(r.mismatches, 0u) << (r.first_mismatches.empty()
                                      ? ""
                                      : r.first_mismatches[0].check + ": " + r.first_mismatches[0].expected + " / " +
                                            r.first_mismatches[0].actual);
  EXPECT_EQ(r.golden_checks, 60u * 8u);
  EXPECT_GT(r.transactions, 60u * 8u);  // centres plus address pairs
  EXPECT_EQ(r.rtl_assertions_failed, 0);
  EXPECT_EQ(r.cycles, 60u * 56u);  // 3 + 4 (2 + 2 + 8) + 5 cycles per frame access
  const RtlCoverage cov = rtl_coverage();
  EXPECT_TRUE(cov.available);
  EXPECT_GT(cov.line_percent(), 80.0);
  EXPECT_GT(cov.toggle_percent(), 50.0);
}

TEST(LsConventionalCosim, NoisyScenesMatchModel) {
  LsConventionalCosimOptions o;
  o.frames = 60;
  o.seed = 4;  // even: shot, kTC and read noise on
  const auto res = run_ls_conventional_cosim(o);
  EXPECT_EQ(res.report.mismatches, 0u);
  EXPECT_EQ(res.report.golden_checks, 0u);
  EXPECT_GT(res.report.transactions, 60u * 8u);
}

TEST(LsConventionalCosim, FlippedAddressBitIsReported) {
  LsConventionalCosimOptions o;
  o.frames = 5;
  o.inject_fault = "address_bit_flip";
  const CosimReport r = run_ls_conventional_cosim(o).report;
  ASSERT_TRUE(r.fault_injected);
  EXPECT_EQ(r.mismatches, 1u) << r.fault_site;
  ASSERT_EQ(count_check(r, "address"), 1);
  const CosimMismatch& m = r.first_mismatches[0];
  EXPECT_GE(m.frame, 1);
  EXPECT_GE(m.row, 0);
  EXPECT_NE(m.expected, m.actual);
  EXPECT_NE(r.fault_site.find("frame " + std::to_string(m.frame) + " row " + std::to_string(m.row)), std::string::npos);
}

TEST(LsConventionalCosim, DroppedRowIsReported) {
  LsConventionalCosimOptions o;
  o.frames = 5;
  o.inject_fault = "dropped_row";
  const CosimReport r = run_ls_conventional_cosim(o).report;
  ASSERT_TRUE(r.fault_injected);
  EXPECT_GE(count_check(r, "address"), 1);
  EXPECT_EQ(count_check(r, "centre"), 1);
  for (const auto& m : r.first_mismatches) {
    EXPECT_EQ(m.frame, 1);
    if (m.check == "address") {
      EXPECT_EQ(m.actual, "no stream");
    }
  }
}

TEST(LsConventionalCosim, CentreOffByOneIsReported) {
  LsConventionalCosimOptions o;
  o.frames = 5;
  o.inject_fault = "centre_off_by_one";
  const CosimReport r = run_ls_conventional_cosim(o).report;
  ASSERT_TRUE(r.fault_injected);
  EXPECT_EQ(r.mismatches, 1u);
  ASSERT_EQ(count_check(r, "centre"), 1);
  EXPECT_EQ(r.first_mismatches[0].frame, 1);
}

TEST(LsConventionalCosim, SameSeedSameRecord) {
  const std::string a = "/tmp/rangesim_lsc_record_a.hex", b = "/tmp/rangesim_lsc_record_b.hex";
  LsConventionalCosimOptions o;
  o.frames = 3;
  o.seed = 7;
  o.record_outputs_path = a;
  const auto res = run_ls_conventional_cosim(o);
  EXPECT_EQ(res.report.mismatches, 0u);
  std::ifstream in(a);
  std::string line;
  int lines = 0;
  while (std::getline(in, line)) ++lines;
  EXPECT_EQ(lines, 3 * 56);  // one line per compared cycle
  std::remove(a.c_str());
  (void)b;
}

TEST(CentreProcessorCosim, MatchesKernel) {
  CosimOptions o;
  o.cycles = 20000;
  const CosimReport r = run_centre_processor_cosim(o);
  EXPECT_EQ(r.mismatches, 0u);
  EXPECT_GE(r.cycles, 20000u);
  EXPECT_GT(r.transactions, 500u);
  EXPECT_EQ(r.rtl_assertions_failed, 0);
}

TEST(CentreProcessorCosim, OffByOneIsReported) {
  CosimOptions o;
  o.cycles = 2000;
  o.inject_fault = "centre_off_by_one";
  const CosimReport r = run_centre_processor_cosim(o);
  ASSERT_TRUE(r.fault_injected);
  EXPECT_EQ(r.mismatches, 1u);
  ASSERT_EQ(count_check(r, "centre"), 1);
}

TEST(CentreProcessorCosim, CountWrapFiresAssertion) {
  CosimOptions o;
  o.cycles = 2000;
  o.inject_fault = "count_wrap";
  const CosimReport r = run_centre_processor_cosim(o);
  ASSERT_TRUE(r.fault_injected);
  EXPECT_EQ(r.rtl_assertions_failed, 1);  // a_count_no_wrap
  EXPECT_GE(r.mismatches, 1u);
}

TEST(MultisamplingSequencerCosim, MatchesKernelThroughResets) {
  CosimOptions o;
  o.cycles = 30000;
  const CosimReport r = run_multisampling_sequencer_cosim(o);
  EXPECT_EQ(r.mismatches, 0u);
  EXPECT_GT(r.transactions, 30000u / 56u * 4u);  // search starts and frame ends
}

TEST(MultisamplingSequencerCosim, LateSearchStartIsReported) {
  CosimOptions o;
  o.cycles = 2000;
  o.inject_fault = "search_start_late";
  const CosimReport r = run_multisampling_sequencer_cosim(o);
  ASSERT_TRUE(r.fault_injected);
  EXPECT_EQ(r.mismatches, 2u);  // the cycle it should have come and the cycle it came
  EXPECT_EQ(count_check(r, "sequencer"), 2);
}

TEST(CosimTargets, NamesUniqueAndFaultsListed) {
  std::set<std::string> names;
  for (const auto& t : cosim_targets()) {
    EXPECT_TRUE(names.insert(t.name).second) << t.name;
    EXPECT_NE(t.run, nullptr);
    EXPECT_FALSE(t.faults.empty()) << t.name;
  }
  for (const char* n : {"ls-conventional", "address_search", "centre_processor", "multisampling_sequencer"})
    EXPECT_EQ(names.count(n), 1u) << n;
}

TEST(CosimCoverage, ParsesVerilatorCoverageData) {
  // Verilator names rangesim's files by absolute path (built-in instances) or relative to rtl/.
  const std::string own = std::string(RANGESIM_SOURCE_DIR) + "/rtl/tof_spad/tdc.sv";
  const std::string data =
      "# SystemC::Coverage-3\n"
      "C '\001f\002" +
      own +
      "\001l\00212\001t\002line\001page\002v_line/top\001o\002x' 3\n"
      "C '\001f\002" +
      own +
      "\001l\00240\001t\002line\001page\002v_line/top\001o\002y' 0\n"
      "C '\001f\002/home/u/my/tdc.sv\001l\0027\001t\002branch\001page\002v_branch/top\001o\002z' 0\n"
      "C '\001f\002/home/u/my/tdc.sv\001l\0029\001t\002branch\001page\002v_branch/top\001o\002w' 1\n"
      "C '\001f\002common/address_search.sv\001l\0025\001t\002line\001page\002v_line/top\001o\002v' 0\n"
      "C '\001t\002toggle\001page\002v_toggle/top\001o\002a' 0\n"
      "C '\001t\002toggle\001page\002v_toggle/top\001o\002b' 5\n";
  const RtlCoverage c = parse_coverage_data(data);
  EXPECT_EQ(c.line_points, 5);
  EXPECT_EQ(c.line_hit, 2);
  EXPECT_EQ(c.toggle_points, 2);
  EXPECT_EQ(c.toggle_hit, 1);
  EXPECT_NEAR(c.line_percent(), 40.0, 1e-9);
  // Uncovered lines by file: rangesim's own by repository path, a user's as given.
  ASSERT_EQ(c.uncovered_lines.size(), 3u);
  EXPECT_EQ(c.uncovered_lines.at("rtl/tof_spad/tdc.sv"), std::set<int>{40});
  EXPECT_EQ(c.uncovered_lines.at("/home/u/my/tdc.sv"), std::set<int>{7});
  EXPECT_EQ(c.uncovered_lines.at("rtl/common/address_search.sv"), std::set<int>{5});
  EXPECT_EQ(c.data, data);
}

}  // namespace
}  // namespace rangesim::tb
