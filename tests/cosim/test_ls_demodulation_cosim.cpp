// Co-simulation of the ls-demodulation readout RTL (frame sequencer + address search) against
// the ticking DemodSensorKernel; injected faults must be reported. One elaboration per process.
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "cosim_test_util.h"
#include "tb/common/cosim_scoreboard.h"
#include "tb/ls_demodulation/cosim.h"

using rangesim::tb::CosimOptions;
using rangesim::tb::CosimReport;
using rangesim::tb::run_ls_demodulation_cosim;

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
}

}  // namespace

TEST(LsDemodulationCosim, RandomFramesMatch) {
  REQUIRE_FRESH_ELABORATION();
  CosimOptions o;
  o.cycles = 12000;
  o.seed = 51;
  expect_clean(run_ls_demodulation_cosim(o), o.cycles);
}

TEST(LsDemodulationCosim, OtherSeedMatches) {
  REQUIRE_FRESH_ELABORATION();
  CosimOptions o;
  o.cycles = 6000;
  o.seed = 52;
  expect_clean(run_ls_demodulation_cosim(o), o.cycles);
}

TEST(LsDemodulationCosim, NoiseFreeCentresMatchGolden) {
  REQUIRE_FRESH_ELABORATION();
  CosimOptions o;
  o.cycles = 12000;
  o.seed =
      13;  // odd: noise-free (seed 13: 81 golden checks in 12000 cycles; some seeds have no row a golden D decides)
  const CosimReport r = run_ls_demodulation_cosim(o);
  expect_clean(r, o.cycles);
  EXPECT_GT(r.golden_checks, 0u);
}

TEST(LsDemodulationCosim, DroppedRowIsReported) {
  REQUIRE_FRESH_ELABORATION();
  CosimOptions o;
  o.cycles = 3000;
  o.seed = 53;
  o.inject_fault = "dropped_row";
  const CosimReport r = run_ls_demodulation_cosim(o);
  ASSERT_TRUE(r.fault_injected);
  const std::string all = text(r);
  EXPECT_NE(all.find("frame 0 row 1 cycle"), std::string::npos) << all;
  EXPECT_NE(all.find("row_valid expected 1 got 0"), std::string::npos) << all;
  EXPECT_EQ(r.rtl_assertions_failed, 0);
}

TEST(LsDemodulationCosim, FlippedAddressBitIsReported) {
  REQUIRE_FRESH_ELABORATION();
  CosimOptions o;
  o.cycles = 3000;
  o.seed = 54;
  o.inject_fault = "address_bit_flip";
  const CosimReport r = run_ls_demodulation_cosim(o);
  ASSERT_TRUE(r.fault_injected) << "nothing streamed";
  EXPECT_NE(text(r).find("addr_bit_o expected"), std::string::npos) << text(r);
  EXPECT_EQ(r.mismatches, 1u) << text(r);  // the scoreboard copy only: the RTL result is right
}
