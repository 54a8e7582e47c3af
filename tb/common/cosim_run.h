#pragma once
// The one way every co-simulation top runs (the harnesses of tb/<sensor>/): elaborate, then open
// the RTL's VCD (Verilator traces only an elaborated model), run a bounded number of clock
// periods, close the trace, read the RTL's coverage counters while the model is alive. The top
// exposes its verilated model as `rtl`.
#include <verilated_vcd_sc.h>

#include <memory>
#include <string>
#include <systemc>

#include "tb/common/cosim_coverage.h"

namespace rangesim::tb {

template <class Top>
void run_cosim_top(Top& top, const std::string& trace_path, sc_core::sc_time period, long long cycles) {
  // Each top ends its run with sc_stop(): SystemC's "Simulation stopped by user" says nothing.
  sc_core::sc_report_handler::set_actions("/OSCI/SystemC", sc_core::SC_INFO, sc_core::SC_DO_NOTHING);
  sc_core::sc_start(sc_core::SC_ZERO_TIME);
  std::unique_ptr<VerilatedVcdSc> tf;
  if (!trace_path.empty()) {
    tf = std::make_unique<VerilatedVcdSc>();
    top.rtl.trace(tf.get(), 99);
    tf->open(trace_path.c_str());
  }
  sc_core::sc_start(period * static_cast<double>(cycles));  // the bound: each top also stops itself
  if (tf) tf->close();
  capture_rtl_coverage();
}

}  // namespace rangesim::tb
