// Co-simulation of the tof-spad readout RTL (TDC with arbitration, histogram with peak and
// centroid sums, row sequencer) against the SystemC kernels; injected faults must be reported.
// One SystemC elaboration per process (gtest_discover_tests).
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <string>

#include "cosim_test_util.h"
#include "tb/common/cosim_scoreboard.h"
#include "tb/tof_spad/cosim.h"

using rangesim::tb::CosimOptions;
using rangesim::tb::CosimReport;
using rangesim::tb::run_tof_spad_cosim;

namespace {

using rangesim::tb::test::print_summary;
using rangesim::tb::test::text;

void expect_clean(const CosimReport& r, std::uint64_t cycles) {
  print_summary(r);
  EXPECT_GE(r.cycles, cycles);
  EXPECT_EQ(r.mismatches, 0u) << text(r);
  EXPECT_EQ(r.rtl_assertions_failed, 0);
  EXPECT_EQ(r.sc_errors, 0);
  EXPECT_GT(r.transactions, 100u);
  EXPECT_GT(r.golden_checks, 0u);
}

std::string record_path(const char* name) {
  const char* dir = std::getenv("RANGESIM_RECORD_DIR");
  return std::string(dir ? dir : ::testing::TempDir().c_str()) + "/" + name;
}

}  // namespace

TEST(TofSpadCosim, RandomRowsMatch) {
  REQUIRE_FRESH_ELABORATION();
  CosimOptions o;
  o.cycles = 40000;
  o.seed = 41;
  expect_clean(run_tof_spad_cosim(o, false, record_path("tof_spad_sequencer.rec")), o.cycles);
}

TEST(TofSpadCosim, OtherSeedMatches) {
  REQUIRE_FRESH_ELABORATION();
  CosimOptions o;
  o.cycles = 50000;
  o.seed = 42;
  expect_clean(run_tof_spad_cosim(o, false), o.cycles);
}

TEST(TdcCosim, HighRatesMatch) {
  REQUIRE_FRESH_ELABORATION();
  CosimOptions o;
  o.cycles = 50000;
  o.seed = 43;
  expect_clean(run_tof_spad_cosim(o, true), o.cycles);
}

TEST(TdcCosim, CodeOffByOneIsReported) {
  REQUIRE_FRESH_ELABORATION();
  CosimOptions o;
  o.cycles = 20000;
  o.seed = 44;
  o.inject_fault = "tdc_code_off_by_one";
  const CosimReport r = run_tof_spad_cosim(o, true);
  ASSERT_TRUE(r.fault_injected);
  const std::string all = text(r);
  EXPECT_NE(all.find("tdc_code expected"), std::string::npos) << all;
  EXPECT_NE(all.find("row 0 column"), std::string::npos) << all;
  EXPECT_EQ(r.rtl_assertions_failed, 0);
}

TEST(TofSpadCosim, DroppedHistogramCountIsReported) {
  REQUIRE_FRESH_ELABORATION();
  CosimOptions o;
  o.cycles = 20000;
  o.seed = 45;
  o.inject_fault = "dropped_histogram_count";
  const CosimReport r = run_tof_spad_cosim(o, false);
  ASSERT_TRUE(r.fault_injected) << "no count to drop";
  const std::string all = text(r);
  EXPECT_NE(all.find("histogram_bin expected"), std::string::npos) << all;
  EXPECT_GT(r.sc_errors, 0);
  EXPECT_EQ(r.rtl_assertions_failed, 0);
}
