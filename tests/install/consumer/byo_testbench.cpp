// A user's own testbench with the installed verification kit (rangesim::cosim_kit): it verilates
// an address search of its own (here rangesim's installed rtl/common/address_search.sv stands in
// for the user's file, tests/install/consumer/CMakeLists.txt), drives random rows from the kit's
// stimulus generator (tb/common/address_search_stimulus.h, the rows rangesim's own co-simulation
// draws) into it and checks every operation against rangesim's reference kernel (AddressSearchKernel) through the
// kit's scoreboard. Prints "byo testbench: ... 0 mismatches" and exits 0 when they agree.
#include <cstdint>
#include <cstdio>
#include <random>
#include <systemc>

#include "Vmy_address_search.h"
#include "systemc/common/address_search_kernel.h"
#include "tb/common/address_search_stimulus.h"
#include "tb/common/cosim_coverage.h"
#include "tb/common/cosim_run.h"
#include "tb/common/cosim_scoreboard.h"
#include "tb/ls_conventional/stimulus.h"
#include "tb/ls_demodulation/stimulus.h"
#include "tb/tof_lockin/stimulus.h"
#include "tb/tof_spad/stimulus.h"

namespace {

constexpr int kColumns = 16, kAddressBits = 4, kSearchCycles = 2, kOperations = 300;

struct Top : sc_core::sc_module {
  sc_core::sc_clock clk{"clk", 10, sc_core::SC_NS};
  sc_core::sc_signal<bool> rst{"rst", true}, start{"start"}, busy{"busy"}, found{"found"}, valid{"valid"}, bit{"bit"},
      done{"done"};
  sc_core::sc_signal<std::uint32_t> act{"act"};
  Vmy_address_search rtl{"rtl"};
  rangesim::tb::CosimReport report;

  SC_HAS_PROCESS(Top);
  explicit Top(sc_core::sc_module_name n) : sc_core::sc_module(n) {
    rtl.clk(clk), rtl.rst(rst), rtl.start_i(start), rtl.act_i(act), rtl.busy_o(busy), rtl.found_o(found);
    rtl.addr_valid_o(valid), rtl.addr_bit_o(bit), rtl.done_o(done);
    SC_THREAD(drive);
  }

  // Inputs change and outputs are sampled at the falling edge; the RTL acts at the rising one.
  void drive() {
    const rangesim::systemc::AddressSearchKernel kernel({kColumns, kAddressBits, 2}, kSearchCycles);
    rangesim::tb::CosimScoreboard board(report);
    std::mt19937_64 rng(7);
    for (int i = 0; i < 3; ++i) wait(clk.negedge_event());
    rst.write(false);
    for (int op = 0; op < kOperations; ++op) {
      wait(clk.negedge_event());
      const rangesim::systemc::ActivationRow row = rangesim::tb::random_address_search_row(kColumns, rng);
      std::uint32_t bits = 0;
      for (int c = 0; c < kColumns; ++c)
        if (row.test(c)) bits |= 1U << c;
      act.write(bits);
      start.write(true);
      wait(clk.negedge_event());
      start.write(false);
      std::uint32_t stream = 0;
      long long cycle = 1;
      while (!done.read()) {
        if (valid.read()) stream = (stream << 1) | (bit.read() ? 1U : 0U);
        wait(clk.negedge_event());
        ++cycle;
      }
      if (valid.read()) stream = (stream << 1) | (bit.read() ? 1U : 0U);
      const rangesim::systemc::AddressSearchResult want = kernel.evaluate(row);
      board.expect("found", -1, op, -1, static_cast<std::uint64_t>(cycle), want.found, found.read());
      board.expect("done_cycle", -1, op, -1, static_cast<std::uint64_t>(cycle), static_cast<long long>(want.done_cycle),
                   cycle);
      if (want.found) {
        board.expect("left", -1, op, -1, static_cast<std::uint64_t>(cycle), want.left,
                     static_cast<int>(stream >> kAddressBits));
        board.expect("right", -1, op, -1, static_cast<std::uint64_t>(cycle), want.right,
                     static_cast<int>(stream & ((1U << kAddressBits) - 1)));
      }
      report.cycles += static_cast<std::uint64_t>(cycle);
    }
    sc_core::sc_stop();
  }
};

}  // namespace

int sc_main(int, char*[]) {
  Top top("top");
  rangesim::tb::run_cosim_top(top, "", sc_core::sc_time(10, sc_core::SC_NS), 100000);
  const rangesim::tb::RtlCoverage cov = rangesim::tb::rtl_coverage();
  std::printf("byo testbench: %d operations, %llu transactions, %llu mismatches, line coverage %.1f %%\n", kOperations,
              static_cast<unsigned long long>(top.report.transactions),
              static_cast<unsigned long long>(top.report.mismatches), cov.line_percent());
  // Every sensor's generator is installed with the kit: one tof-lockin readout setup, as the
  // built-in target draws it at --seed 1.
  std::mt19937_64 rng(1);
  const rangesim::tb::TofLockinSetup lockin = rangesim::tb::random_tof_lockin_setup(20000, 1, rng);
  std::printf("kit generator: tof-lockin setup %d x %d pixels, %d-bit ADC, %lld frames\n", lockin.cfg.pixel.rows,
              lockin.cfg.pixel.columns, lockin.cfg.readout.adc_bits, lockin.frames);
  for (const auto& m : top.report.first_mismatches)
    std::printf("  %s\n", rangesim::tb::CosimScoreboard::format(m).c_str());
  return top.report.mismatches == 0 && top.report.transactions > kOperations ? 0 : 1;
}
