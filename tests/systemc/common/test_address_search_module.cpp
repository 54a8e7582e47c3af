// The AddressSearch sc_module in a small clocked testbench. Each test elaborates, so each needs
// its own process: ctest runs them that way (gtest_discover_tests); a second elaborating test in
// one process skips itself instead of failing.
#include <gtest/gtest.h>

#include <random>
#include <systemc>
#include <vector>

#include "core/ls_conventional/config.h"
#include "tests/systemc/elaboration_guard.h"
#include "systemc/common/address_search.h"

namespace rs = rangesim::systemc;
using rangesim::AddressSearchConfig;

namespace {

struct Bench : sc_core::sc_module {
  sc_core::sc_clock clk{"clk", 10, sc_core::SC_NS};
  sc_core::sc_signal<bool> rst{"rst", true}, start{"start"};
  sc_core::sc_signal<rs::ActivationRow> act{"act"};
  sc_core::sc_signal<bool> busy{"busy"}, found{"found"}, valid{"valid"}, bit{"bit"}, done{"done"};
  rs::AddressSearch dut;

  std::vector<rs::ActivationRow> rows;  // stimulus, one operation each
  std::vector<unsigned> streams;        // observed stream bits per operation
  std::vector<bool> founds;             // found_o at done_o
  std::vector<long long> done_cycles;   // cycle k of done_o, per operation
  long long cycle = 0, start_cycle = 0;
  unsigned bits = 0;

  SC_HAS_PROCESS(Bench);
  Bench(sc_core::sc_module_name n, const AddressSearchConfig& cfg) : sc_core::sc_module(n), dut("dut", cfg, 2) {
    dut.clk_i(clk);
    dut.rst_i(rst);
    dut.start_i(start);
    dut.act_i(act);
    dut.busy_o(busy);
    dut.found_o(found);
    dut.addr_valid_o(valid);
    dut.addr_bit_o(bit);
    dut.done_o(done);
    SC_THREAD(drive);
    sensitive << clk.posedge_event();
    SC_METHOD(watch);
    sensitive << clk.negedge_event();
    dont_initialize();
  }

  void drive() {
    wait();
    wait();
    rst.write(false);
    for (const rs::ActivationRow& row : rows) {
      start.write(true);
      act.write(row);
      start_cycle = cycle;
      wait();
      start.write(false);
      // Wait for done_o on the output (not a fixed schedule: this tests the module's own pins).
      do wait();
      while (!done.read());
      wait();
    }
    sc_core::sc_stop();
  }

  void watch() {
    ++cycle;
    if (valid.read()) bits = (bits << 1) | (bit.read() ? 1U : 0U);
    if (done.read()) {
      streams.push_back(bits);
      founds.push_back(found.read());
      done_cycles.push_back(cycle - start_cycle - 1);
      bits = 0;
    }
  }
};

}  // namespace

TEST(AddressSearchModule, StreamsRandomRowsInTheDocumentedCycles) {
  REQUIRE_FRESH_ELABORATION();
  const AddressSearchConfig cfg{16, 4, 2};
  Bench bench("bench", cfg);
  std::mt19937_64 rng(7);
  for (int i = 0; i < 200; ++i) {
    rs::ActivationRow row(cfg.columns);
    if (i % 7 != 0) {  // every 7th row empty
      for (int c = 0; c < cfg.columns; ++c) row.set(c, (rng() % 8) == 0);
    }
    bench.rows.push_back(row);
  }
  const long long cycle_limit = 200 * (1 + 2 + 8) + 10;
  sc_core::sc_start(10.0 * cycle_limit, sc_core::SC_NS);  // bounded
  ASSERT_EQ(bench.streams.size(), bench.rows.size()) << "did not finish in the cycle limit";
  for (std::size_t i = 0; i < bench.rows.size(); ++i) {
    const rs::ActivationRow& row = bench.rows[i];
    ASSERT_EQ(bench.founds[i], row.any()) << i;
    ASSERT_EQ(bench.done_cycles[i], row.any() ? 2 + 8 : 2) << i;
    if (row.any()) {
      ASSERT_EQ(bench.streams[i], (unsigned(row.first()) << 4) | unsigned(row.last())) << i;
    }
  }
  EXPECT_EQ(sc_core::sc_report_handler::get_count(sc_core::SC_ERROR), 0);
}

TEST(AddressSearchModule, WrongRowWidthIsAnScError) {
  REQUIRE_FRESH_ELABORATION();
  Bench bench("bench", AddressSearchConfig{16, 4, 2});
  bench.rows.push_back(rs::ActivationRow(15));  // one column short
  // SC_REPORT_ERROR in a process comes out of sc_start as an exception.
  EXPECT_THROW(sc_core::sc_start(1, sc_core::SC_US), sc_core::sc_report);
  EXPECT_EQ(sc_core::sc_report_handler::get_count(sc_core::SC_ERROR), 1);
}

TEST(AddressSearchModule, RejectsBadParametersAtConstruction) {
  REQUIRE_FRESH_ELABORATION();
  EXPECT_THROW(rs::AddressSearch("bad", AddressSearchConfig{375, 8, 2}), std::invalid_argument);
}
