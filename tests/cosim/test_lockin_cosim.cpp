// Co-simulation of the tof-lockin readout RTL (gate generator, column ADC, frame sequencer)
// against the SystemC cycle kernels: random runs with zero mismatches, each injected fault
// reported with its place, and the Icarus replay records. One SystemC elaboration per process
// (gtest_discover_tests runs each test alone).
#include <gtest/gtest.h>

#include <cstdio>
#include <iterator>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <string>

#include "cosim_test_util.h"
#include "tb/common/cosim_scoreboard.h"
#include "tb/tof_lockin/lockin_gate_generator_cosim.h"
#include "tb/common/cosim_target.h"

using rangesim::tb::CosimOptions;
using rangesim::tb::CosimReport;

namespace {

using rangesim::tb::test::print_summary;
using rangesim::tb::test::text;

void expect_clean(const CosimReport& r, std::uint64_t cycles, std::uint64_t min_transactions) {
  print_summary(r);
  EXPECT_GE(r.cycles, cycles);
  EXPECT_EQ(r.mismatches, 0u) << text(r);
  EXPECT_EQ(r.rtl_assertions_failed, 0);
  EXPECT_EQ(r.sc_errors, 0);
  EXPECT_GE(r.transactions, min_transactions);
  EXPECT_FALSE(r.fault_injected);
}

// The fault must be applied, reported, and the first report must name the place.
void expect_caught(const CosimReport& r, const std::string& check, const std::string& where) {
  ASSERT_TRUE(r.fault_injected);
  ASSERT_GT(r.mismatches, 0u) << "fault not detected: " << r.fault_site;
  EXPECT_GT(r.sc_errors, 0);
  EXPECT_EQ(r.rtl_assertions_failed, 0);  // a scoreboard fault, not an RTL protocol error
  const std::string all = text(r);
  EXPECT_NE(all.find(check), std::string::npos) << all;
  EXPECT_NE(all.find(where), std::string::npos) << all;
}

// ctest passes a directory for the Icarus replay records (fixture lockin_records).
std::string record_path(const char* name) {
  const char* dir = std::getenv("RANGESIM_RECORD_DIR");
  return std::string(dir ? dir : ::testing::TempDir().c_str()) + "/" + name;
}

}  // namespace

TEST(LockinCosimTargets, ListedWithTheirFaults) {
  // Every sensor's targets through the registry (core/sensor_list.h), sensors first.
  const auto& targets = rangesim::tb::cosim_targets();
  const char* names[] = {"ls-conventional",
                         "ls-conventional-full",
                         "ls-demodulation",
                         "tof-lockin",
                         "tof-spad",
                         "address_search",
                         "centre_processor",
                         "multisampling_sequencer",
                         "lockin_gate_generator",
                         "column_adc",
                         "tdc"};
  ASSERT_EQ(targets.size(), std::size(names));
  for (std::size_t i = 0; i < targets.size(); ++i) EXPECT_STREQ(targets[i].name, names[i]);
  for (const auto& t : targets) {
    EXPECT_FALSE(t.faults.empty()) << t.name;
    EXPECT_NE(t.run, nullptr);
  }
}

TEST(LockinGateGeneratorCosim, RandomOperationsMatch) {
  REQUIRE_FRESH_ELABORATION();
  CosimOptions o;
  o.cycles = 50000;
  o.seed = 11;
  const CosimReport r = run_lockin_gate_generator_cosim(o, record_path("lockin_gate_generator.rec"));
  expect_clean(r, o.cycles, 500);  // gate edges: >= 6 per period
}

TEST(LockinGateGeneratorCosim, GateShiftedOneCycleIsReported) {
  REQUIRE_FRESH_ELABORATION();
  CosimOptions o;
  o.cycles = 5000;
  o.seed = 12;
  o.inject_fault = "gate_shift";
  const CosimReport r = rangesim::tb::run_lockin_gate_generator_cosim(o);
  expect_caught(r, "gate_edge", "tx2 rise");
  EXPECT_NE(text(r).find("frame 1 "), std::string::npos) << text(r);  // operation 1
}

// A protocol violation (T_rep shrinking under the running counter) fires the named assertion.
TEST(LockinGateGeneratorCosim, PeriodChangeWhileBusyFiresRtlAssertion) {
  REQUIRE_FRESH_ELABORATION();
  CosimOptions o;
  o.cycles = 3000;
  o.seed = 13;
  o.inject_fault = "period_change_while_busy";
  const CosimReport r = rangesim::tb::run_lockin_gate_generator_cosim(o);
  ASSERT_TRUE(r.fault_injected);
  EXPECT_EQ(r.rtl_assertions_failed, 1);
  EXPECT_GT(r.mismatches, 0u);
}

TEST(ColumnAdcCosim, RandomConversionsMatch) {
  REQUIRE_FRESH_ELABORATION();
  CosimOptions o;
  o.cycles = 50000;
  o.seed = 21;
  const CosimReport r = rangesim::tb::run_column_adc_cosim(o, record_path("column_adc.rec"));
  expect_clean(r, o.cycles, 20);
}

TEST(ColumnAdcCosim, CodeOffByOneIsReported) {
  REQUIRE_FRESH_ELABORATION();
  CosimOptions o;
  o.cycles = 10000;
  o.seed = 22;
  o.inject_fault = "adc_code_off_by_one";
  const CosimReport r = rangesim::tb::run_column_adc_cosim(o);
  expect_caught(r, "adc_code expected", "frame 2 ");  // conversion 2
  EXPECT_EQ(r.mismatches, 1u) << text(r);
}

TEST(TofLockinCosim, RandomFramesMatchKernelAndRanges) {
  REQUIRE_FRESH_ELABORATION();
  CosimOptions o;
  o.cycles = 60000;
  o.seed = 31;
  const CosimReport r = rangesim::tb::run_tof_lockin_cosim(o);
  expect_clean(r, o.cycles, 100);
  EXPECT_GT(r.golden_checks, 0u);
}

TEST(TofLockinCosim, OtherSeedsMatch) {
  REQUIRE_FRESH_ELABORATION();
  CosimOptions o;
  o.cycles = 30000;
  o.seed = 32;
  const CosimReport r = rangesim::tb::run_tof_lockin_cosim(o);
  expect_clean(r, o.cycles, 100);
}

TEST(TofLockinCosim, WritesRtlWaveform) {
  REQUIRE_FRESH_ELABORATION();
  CosimOptions o;
  o.cycles = 1000;
  o.seed = 35;
  o.trace_path = ::testing::TempDir() + "tof_lockin_cosim.vcd";
  std::remove(o.trace_path.c_str());
  const CosimReport r = rangesim::tb::run_tof_lockin_cosim(o);
  EXPECT_EQ(r.mismatches, 0u) << text(r);
  std::ifstream f(o.trace_path);
  const std::string vcd((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  EXPECT_NE(vcd.find("$enddefinitions"), std::string::npos);
  EXPECT_NE(vcd.find("tx1_o"), std::string::npos);
}

TEST(TofLockinCosim, GateShiftedOneCycleIsReported) {
  REQUIRE_FRESH_ELABORATION();
  CosimOptions o;
  o.cycles = 2000;
  o.seed = 33;
  o.inject_fault = "gate_shift";
  const CosimReport r = rangesim::tb::run_tof_lockin_cosim(o);
  expect_caught(r, "tx2_o expected", "frame 0 ");
  EXPECT_NE(text(r).find("phase_boundary"), std::string::npos) << text(r);
}

TEST(TofLockinCosim, AdcCodeOffByOneIsReported) {
  REQUIRE_FRESH_ELABORATION();
  CosimOptions o;
  o.cycles = 2000;
  o.seed = 34;
  o.inject_fault = "adc_code_off_by_one";
  const CosimReport r = rangesim::tb::run_tof_lockin_cosim(o);
  expect_caught(r, "adc_code tap1 expected", "frame 0 row 1 column 0 ");
}
