#pragma once
// The one way every co-simulation top runs (the harnesses of tb/<sensor>/): elaborate, then open
// the RTL's VCD (Verilator traces only an elaborated model), run a bounded number of clock
// periods, close the trace, read the RTL's coverage counters while the model is alive. The top
// exposes its verilated model as `rtl`; a top with `trace_expected(systemc::Waveform&)` adds the
// model's expected values, which end up in the same VCD under the scope "expected"
// (tb/common/vcd_merge.h), beside the RTL's; beside the trace goes its GTKWave save file
// (tb/common/cosim_save_file.h).
#include <verilated_vcd_sc.h>

#include <cstdio>
#include <memory>
#include <type_traits>
#include <string>
#include <utility>
#include <vector>
#include <systemc>

#include "systemc/common/waveform.h"
#include "tb/common/cosim_coverage.h"
#include "tb/common/cosim_save_file.h"
#include "tb/common/vcd_merge.h"

namespace rangesim::tb {

template <class Top, class = void>
struct TracesExpected : std::false_type {};
template <class Top>
struct TracesExpected<Top,
                      std::void_t<decltype(std::declval<Top&>().trace_expected(std::declval<systemc::Waveform&>()))>>
    : std::true_type {};

template <class Top>
void run_cosim_top(Top& top, const std::string& trace_path, sc_core::sc_time period, long long cycles) {
  // Each top ends its run with sc_stop(): SystemC's "Simulation stopped by user" says nothing.
  sc_core::sc_report_handler::set_actions("/OSCI/SystemC", sc_core::SC_INFO, sc_core::SC_DO_NOTHING);
  sc_core::sc_start(sc_core::SC_ZERO_TIME);
  std::unique_ptr<VerilatedVcdSc> tf;
  std::unique_ptr<systemc::Waveform> expected;
  const std::string expected_base = trace_path + ".expected";
  if (!trace_path.empty()) {
    tf = std::make_unique<VerilatedVcdSc>();
    top.rtl.trace(tf.get(), 99);
    tf->open(trace_path.c_str());
    if constexpr (TracesExpected<Top>::value) {
      expected = std::make_unique<systemc::Waveform>(expected_base, false);
      top.trace_expected(*expected);
    }
  }
  sc_core::sc_start(period * static_cast<double>(cycles));  // the bound: each top also stops itself
  if (tf) tf->close();
  if (expected) {
    expected->close();
    merge_vcd(trace_path, expected_base + ".vcd", "expected");
    std::remove((expected_base + ".vcd").c_str());
  }
  if (tf) write_cosim_save_file(trace_path, expected ? expected->signals() : std::vector<systemc::Waveform::Signal>{});
  capture_rtl_coverage();
}

}  // namespace rangesim::tb
