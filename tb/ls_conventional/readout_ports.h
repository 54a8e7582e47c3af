#pragma once
// The ports of rtl/ls_conventional/ls_conventional_readout.sv as SystemC signals bound to a
// verilated instance, and the decoding of its outputs (packed per-row buses, row r at
// [r*W +: W]). Shared by the co-simulation harness (tb/ls_conventional/cosim_harness.h) and the
// RTL throughput bench (app/bench/bench_rtl_readout.cpp), for any instance: the C++ port types
// follow the instance's widths (tb/common/cosim_ports.h), the field widths its config.
#include <cstdint>
#include <systemc>
#include <utility>

#include "core/ls_conventional/config.h"
#include "systemc/ls_conventional/sensor_kernel.h"
#include "tb/common/cosim_ports.h"
#include "tb/common/verilog_parameters.h"

namespace rangesim::tb {

// Widths of the readout's output fields, as the RTL derives them from its parameters
// (SamplingBits, CentreBits, SumBits, CountBits in ls_conventional_readout.sv).
struct LsReadoutFields {
  int sampling, centre, sum, count;
  explicit LsReadoutFields(const LsConventionalConfig& c)
      : sampling(clog2(c.multisampling.samplings + 1)),
        centre(c.search.address_bits + 8),
        sum(c.search.address_bits + 1 + clog2(c.multisampling.samplings + 1)),
        count(clog2(c.multisampling.samplings + 1)) {}
};

template <class VTop>
struct LsReadoutSignals {
  template <class Member>
  using Sig = sc_core::sc_signal<PortData<Member>>;
  Sig<decltype(std::declval<VTop&>().cmp_i)> cmp{"cmp"};
  Sig<decltype(std::declval<VTop&>().phase_o)> phase{"phase"};
  Sig<decltype(std::declval<VTop&>().pix_reset_o)> pix_reset{"pix_reset"};
  Sig<decltype(std::declval<VTop&>().latch_o)> latch{"latch"};
  Sig<decltype(std::declval<VTop&>().search_start_o)> search_start{"search_start"};
  Sig<decltype(std::declval<VTop&>().frame_done_o)> frame_done{"frame_done"};
  Sig<decltype(std::declval<VTop&>().sampling_o)> sampling{"sampling"};
  Sig<decltype(std::declval<VTop&>().frame_o)> frame{"frame"};
  Sig<decltype(std::declval<VTop&>().busy_o)> busy{"busy"};
  Sig<decltype(std::declval<VTop&>().addr_valid_o)> addr_valid{"addr_valid"};
  Sig<decltype(std::declval<VTop&>().addr_bit_o)> addr_bit{"addr_bit"};
  Sig<decltype(std::declval<VTop&>().centre_valid_o)> centre_valid{"centre_valid"};
  Sig<decltype(std::declval<VTop&>().centre_q_o)> centre_q{"centre_q"};
  Sig<decltype(std::declval<VTop&>().sum_o)> sum{"sum"};
  Sig<decltype(std::declval<VTop&>().count_o)> count{"count"};

  void bind(VTop& rtl, sc_core::sc_clock& clk, sc_core::sc_signal<bool>& rst) {
    rtl.clk(clk);
    rtl.rst(rst);
    rtl.cmp_i(cmp);
    rtl.phase_o(phase);
    rtl.pix_reset_o(pix_reset);
    rtl.latch_o(latch);
    rtl.search_start_o(search_start);
    rtl.frame_done_o(frame_done);
    rtl.sampling_o(sampling);
    rtl.frame_o(frame);
    rtl.busy_o(busy);
    rtl.addr_valid_o(addr_valid);
    rtl.addr_bit_o(addr_bit);
    rtl.centre_valid_o(centre_valid);
    rtl.centre_q_o(centre_q);
    rtl.sum_o(sum);
    rtl.count_o(count);
  }

  // The sequencer's pins (frame_o is 32 bits wide).
  systemc::MultisamplingSequencerPins sequencer_pins(const LsReadoutFields& f) const {
    systemc::MultisamplingSequencerPins p;
    p.phase = static_cast<systemc::ReadoutPhase>(port_field(phase.read(), 0, 3));
    p.pix_reset = pix_reset.read();
    p.latch = latch.read();
    p.search_start = search_start.read();
    p.frame_done = frame_done.read();
    p.sampling = static_cast<int>(port_field(sampling.read(), 0, f.sampling));
    p.frame = port_field(frame.read(), 0, 32);
    return p;
  }

  // Row r's centre processor outputs.
  systemc::CentreProcessorPins centre_pins(const LsReadoutFields& f, int r) const {
    systemc::CentreProcessorPins p;
    p.valid = port_bit(centre_valid.read(), r);
    p.centre_q = static_cast<std::uint32_t>(port_field(centre_q.read(), r * f.centre, f.centre));
    p.sum = static_cast<std::uint32_t>(port_field(sum.read(), r * f.sum, f.sum));
    p.count = static_cast<int>(port_field(count.read(), r * f.count, f.count));
    return p;
  }
};

}  // namespace rangesim::tb
