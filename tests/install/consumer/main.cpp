// Consumer of the installed rangesim package: golden frame timing, the SystemC-view kernel and
// module, and (if packaged) the verilated RTL, in one sc_main. Prints "rangesim consumer OK".
#include <cstdio>
#include <string>
#include <systemc>

#include "core/ls_conventional/config.h"
#include "golden/ls_conventional/frame_timing.h"
#include "systemc/common/address_search.h"
#include "systemc/common/address_search_kernel.h"
#if CONSUMER_WITH_RTL
#include "Vaddress_search_small.h"
#include "rtl/instance_presets.h"
#endif

int sc_main(int, char*[]) {
  const rangesim::FrameTimingConfig timing;
  const rangesim::golden::FrameTiming ft = rangesim::golden::frame_timing(timing, 4);

  // One search operation of the kernel, start to next start, must be what golden counts.
  rangesim::systemc::AddressSearchKernel kernel(rangesim::AddressSearchConfig{}, timing.search_cycles);
  rangesim::systemc::ActivationRow row(rangesim::AddressSearchConfig{}.columns);
  row.set(100);
  row.set(103);
  const long long before = kernel.edges();
  const rangesim::systemc::AddressSearchResult r = kernel.run(row);
  const long long per_sampling = kernel.edges() - before;
  const long long expected = timing.reset_cycles + 4 * per_sampling + timing.output_cycles;
  std::printf("golden frame cycles %lld, from the kernel %lld; left %d right %d\n", ft.frame_cycles, expected, r.left,
              r.right);
  bool ok = r.found && r.left == 100 && r.right == 103 && ft.frame_cycles == expected;

  // Elaborate the sc_module (and the verilated RTL) and clock them a little.
  sc_core::sc_clock clk("clk", 10, sc_core::SC_NS);
  sc_core::sc_signal<bool> rst("rst", true), start("start");
  sc_core::sc_signal<bool> o[10];
  sc_core::sc_signal<rangesim::systemc::ActivationRow> act("act");
  rangesim::systemc::AddressSearch model("model", rangesim::AddressSearchConfig{});
  model.clk_i(clk);
  model.rst_i(rst);
  model.start_i(start);
  model.act_i(act);
  model.busy_o(o[0]);
  model.found_o(o[1]);
  model.addr_valid_o(o[2]);
  model.addr_bit_o(o[3]);
  model.done_o(o[4]);
#if CONSUMER_WITH_RTL
  sc_core::sc_signal<std::uint32_t> act_rtl("act_rtl");
  Vaddress_search_small rtl("rtl");
  rtl.clk(clk);
  rtl.rst(rst);
  rtl.start_i(start);
  rtl.act_i(act_rtl);
  rtl.busy_o(o[5]);
  rtl.found_o(o[6]);
  rtl.addr_valid_o(o[7]);
  rtl.addr_bit_o(o[8]);
  rtl.done_o(o[9]);
  for (const auto& i : rangesim::rtl::kInstancePresets)
    if (std::string(i.prefix) == "Vaddress_search_small") std::printf("RTL instance %s from %s\n", i.prefix, i.file);
#endif
  sc_core::sc_start(50, sc_core::SC_NS);
  ok = ok && sc_core::sc_report_handler::get_count(sc_core::SC_ERROR) == 0 && !o[0].read();
  std::printf(ok ? "rangesim consumer OK\n" : "rangesim consumer FAILED\n");
  return ok ? 0 : 1;
}
