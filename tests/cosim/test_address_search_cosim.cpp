// RTL (verilated) vs SystemC model co-simulation of address_search, with negative tests that
// inject faults and expect the checkers to report them. One elaboration per test process.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>

#include "core/ls_conventional/config.h"
#include "core/preset.h"
#include "tb/common/address_search_cosim.h"

using rangesim::tb::AddressSearchCosimOptions;
using rangesim::tb::AddressSearchCosimReport;
using rangesim::tb::AddressSearchInstance;
using rangesim::tb::run_address_search_cosim;

namespace {

bool claim_elaboration() {
  static bool used = false;
  const bool first = !used;
  used = true;
  return first;
}

#define REQUIRE_FRESH_ELABORATION()                           \
  if (!claim_elaboration())                                   \
  GTEST_SKIP() << "one SystemC elaboration per process: run " \
                  "this test alone (ctest does)"

std::string all(const AddressSearchCosimReport& r) {
  std::string s;
  for (const std::string& m : r.mismatches) s += m + "\n";
  return s;
}

void expect_clean(const AddressSearchCosimReport& r, int operations) {
  EXPECT_TRUE(r.finished) << "stopped at cycle " << r.cycles;
  EXPECT_EQ(r.operations_done, operations);
  EXPECT_EQ(r.mismatch_count, 0) << all(r);
  EXPECT_FALSE(r.rtl_assertion_failed);
  EXPECT_EQ(r.sc_errors, 0);
  EXPECT_GE(r.transactions_compared, operations);  // at least one done per operation
}

}  // namespace

// The full-size instance is the chip: its sizes are those of presets/ls-conventional.toml (its
// instance preset inherits them), and the small one is what rtl/ls_conventional/instances/small.toml
// says.
TEST(AddressSearchRtl, InstancesHaveTheirPresetsSizes) {
  const rangesim::LsConventionalConfig chip =
      rangesim::ls_conventional_from_params(rangesim::load_preset("ls-conventional"));
  const rangesim::tb::AddressSearchShape full =
      rangesim::tb::address_search_shape(rangesim::tb::AddressSearchInstance::Default);
  EXPECT_STREQ(full.prefix, "Vaddress_search");
  EXPECT_EQ(full.columns, chip.search.columns);
  EXPECT_EQ(full.columns, 375);
  EXPECT_EQ(full.address_bits, chip.search.address_bits);
  EXPECT_EQ(full.search_cycles, chip.timing.search_cycles);
  const rangesim::tb::AddressSearchShape small =
      rangesim::tb::address_search_shape(rangesim::tb::AddressSearchInstance::Small);
  EXPECT_EQ(small.columns, 16);
  EXPECT_EQ(small.address_bits, 4);
  EXPECT_EQ(small.search_cycles, 2);
}

TEST(AddressSearchCosim, SmallInstance500RowsMatch) {
  REQUIRE_FRESH_ELABORATION();
  AddressSearchCosimOptions o;
  o.instance = AddressSearchInstance::Small;
  o.frames = 5;
  o.rows_per_frame = 100;
  expect_clean(run_address_search_cosim(o), 500);
}

TEST(AddressSearchCosim, PresetInstance500RowsMatch) {
  REQUIRE_FRESH_ELABORATION();
  AddressSearchCosimOptions o;
  o.instance = AddressSearchInstance::Default;
  o.frames = 2;
  o.rows_per_frame = 250;
  o.seed = 2;
  o.max_gap_cycles = 0;  // strictly back to back, as in the frame schedule
  expect_clean(run_address_search_cosim(o), 500);
}

TEST(AddressSearchCosim, FlippedRtlAddressBitIsReported) {
  REQUIRE_FRESH_ELABORATION();
  AddressSearchCosimOptions o;
  o.frames = 2;
  o.rows_per_frame = 20;
  o.seed = 3;
  o.fault_operation = 23;  // frame 1 row 3, or the next row that streams
  o.fault_bit = 5;         // right address, second bit (B = 4)
  const AddressSearchCosimReport r = run_address_search_cosim(o);
  ASSERT_EQ(r.fault_frame, 1);
  ASSERT_GE(r.fault_row, 3);
  ASSERT_GT(r.mismatch_count, 0) << "fault not detected";
  EXPECT_GT(r.sc_errors, 0);
  const std::string text = all(r);
  const std::string where = "frame 1 row " + std::to_string(r.fault_row) + " cycle ";
  EXPECT_NE(text.find(where), std::string::npos) << text;
  EXPECT_NE(text.find("addr_bit_o expected"), std::string::npos) << text;
  EXPECT_NE(text.find("right address expected"), std::string::npos) << text;
}

TEST(AddressSearchCosim, StartWhileBusyFiresRtlAssertion) {
  REQUIRE_FRESH_ELABORATION();
  AddressSearchCosimOptions o;
  o.frames = 1;
  o.rows_per_frame = 10;
  o.restart_operation = 4;
  o.restart_cycle = 1;  // start again in cycle k = 1 (searching)
  const AddressSearchCosimReport r = run_address_search_cosim(o);
  EXPECT_TRUE(r.rtl_assertion_failed);
  EXPECT_EQ(r.mismatch_count, 0) << all(r);  // both views ignore the extra start
}

TEST(AddressSearchCosim, WritesOneWaveformWithBothViews) {
  REQUIRE_FRESH_ELABORATION();
  AddressSearchCosimOptions o;
  o.frames = 1;
  o.rows_per_frame = 5;
  o.trace_path = ::testing::TempDir() + "address_search_cosim.vcd";
  expect_clean(run_address_search_cosim(o), 5);
  std::ifstream f(o.trace_path);
  std::string text((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  EXPECT_NE(text.find("$scope module cosim.rtl $end"), std::string::npos);  // the RTL (Verilator)
  EXPECT_NE(text.find("$scope module expected $end"), std::string::npos);   // the model beside it
  EXPECT_NE(text.find("addr_bit"), std::string::npos);
}
