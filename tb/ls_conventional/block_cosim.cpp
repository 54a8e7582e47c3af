// Co-simulation harnesses of centre_processor and multisampling_sequencer: see block_cosim.h.
// Same timing discipline as the other harnesses: kernels tick and stimulus is written on the
// rising edge; both views are sampled on the falling edge.
#include "tb/ls_conventional/block_cosim.h"

#include "tb/common/cosim_run.h"

#include <verilated.h>
#include <verilated_vcd_sc.h>

#include <algorithm>
#include <memory>
#include <random>
#include <sstream>
#include <string>
#include <systemc>
#include <vector>

#include "Vcentre_processor_small.h"
#include "Vmultisampling_sequencer_small.h"
#include "systemc/ls_conventional/centre_processor_kernel.h"
#include "systemc/ls_conventional/multisampling_sequencer_kernel.h"
#include "tb/common/cosim_ports.h"
#include "tb/common/cosim_scoreboard.h"
#include "tb/common/instance_preset.h"
#include "tb/common/verilog_parameters.h"
#include "tb/ls_conventional/cosim.h"
#include "tb/ls_conventional/verilog_parameters.h"

namespace rangesim::tb {
namespace {

constexpr int kResetEdges = 3;

// The blocks' instances share one instance preset (rtl/ls_conventional/instances/small.toml), so
// both kernels run its configuration.
const LsConventionalConfig& small_config() {
  static const LsConventionalConfig c = ls_conventional_from_params(instance_preset("Vcentre_processor_small"));
  return c;
}

void add(CosimReport& r, CosimMismatch m) { CosimScoreboard(r).add(std::move(m)); }

template <class Top>
void run_top(Top& top, const CosimOptions& o, sc_core::sc_time period, long long cycles) {
  run_cosim_top(top, o.trace_path, period, cycles + kResetEdges);
}

// ---------------- centre_processor ----------------

class CentreTop : public sc_core::sc_module {
 public:
  sc_core::sc_clock clk;
  sc_core::sc_signal<bool> rst{"rst", true}, clear{"clear"}, valid_in{"valid_in"}, bit_in{"bit_in"};
  Vcentre_processor_small rtl{"rtl"};
  sc_core::sc_signal<PortData<decltype(rtl.valid_o)>> valid{"valid"};
  sc_core::sc_signal<PortData<decltype(rtl.centre_q_o)>> centre_q{"centre_q"};
  sc_core::sc_signal<PortData<decltype(rtl.sum_o)>> sum{"sum"};
  sc_core::sc_signal<PortData<decltype(rtl.count_o)>> count{"count"};

  SC_HAS_PROCESS(CentreTop);
  CentreTop(sc_core::sc_module_name n, const CosimOptions& o, sc_core::sc_time period)
      : sc_core::sc_module(n), clk("clk", period), o_(o), kernel_(small_config().search.address_bits), rng_(o.seed) {
    rtl.clk(clk);
    rtl.rst(rst);
    rtl.clear_i(clear);
    rtl.addr_valid_i(valid_in);
    rtl.addr_bit_i(bit_in);
    rtl.valid_o(valid);
    rtl.centre_q_o(centre_q);
    rtl.sum_o(sum);
    rtl.count_o(count);
    report.target = "centre_processor";
    e_ = kernel_.pins();
    SC_METHOD(on_posedge);
    sensitive << clk.posedge_event();
    dont_initialize();
    SC_METHOD(on_negedge);
    sensitive << clk.negedge_event();
    dont_initialize();
  }
  CosimReport report;

  // The kernel's pins of every cycle beside the RTL's (tb/common/cosim_run.h), as compared.
  void trace_expected(systemc::Waveform& w) {
    w.add(e_.valid, "centre_processor", "valid");
    w.add(e_.centre_q, "centre_processor", "centre_q");
    w.add(e_.sum, "centre_processor", "sum");
    w.add(e_.count, "centre_processor", "count");
  }

 private:
  // Stimulus of the next cycle: a clear every few streams (at most SAMPLINGS between clears,
  // unless the count_wrap fault asks for one more), streams of 2B contiguous bits, random gaps.
  void on_posedge() {
    const long long e = edges_++;
    // The edge that ends the current cycle: the kernel sees the current inputs.
    if (e == kResetEdges - 1) {
      kernel_.clear();
      rst.write(false);
    } else if (e >= kResetEdges) {
      systemc::AddressSearchPins pins;
      pins.addr_valid = valid_in.read();
      pins.addr_bit = bit_in.read();
      kernel_.tick(clear.read(), pins);
    }
    if (e < kResetEdges - 1) return;
    const int B = small_config().search.address_bits, N = small_config().multisampling.samplings;
    std::uniform_int_distribution<int> gap(0, 3), bitd(0, 1);
    bool c = false, v = false, b = false;
    if (stream_left_ > 0) {
      v = true;
      b = bitd(rng_) != 0;
      --stream_left_;
    } else if (gap_left_ > 0) {
      --gap_left_;
    } else {
      const int limit = (o_.inject_fault == "count_wrap" && !report.fault_injected) ? N + 1 : N;
      if (streams_ >= limit || std::uniform_int_distribution<int>(0, 9)(rng_) == 0) {
        if (streams_ > N) {
          report.fault_injected = true;
          report.fault_site = "cycle " + std::to_string(e - kResetEdges + 1) + ": " + std::to_string(streams_) +
                              " streams without a clear";
        }
        c = true;
        streams_ = 0;
      } else {
        v = true;
        b = bitd(rng_) != 0;
        stream_left_ = 2 * B - 1;
        ++streams_;
        CosimScoreboard(report).count("centre");  // one accumulated sampling
      }
      gap_left_ = gap(rng_);
    }
    clear.write(c);
    valid_in.write(v);
    bit_in.write(b);
  }

  void on_negedge() {
    const long long period = edges_ - 1;
    if (period < kResetEdges - 1) return;
    const long long cycle = period - (kResetEdges - 1);
    report.cycles = static_cast<std::uint64_t>(cycle + 1);
    const int B = small_config().search.address_bits, N = small_config().multisampling.samplings;
    const int cb = B + 8, sumb = B + 1 + clog2(N + 1), cntb = clog2(N + 1);
    const systemc::CentreProcessorPins m = kernel_.pins();
    e_ = m;
    systemc::CentreProcessorPins g;
    g.valid = valid.read();
    g.centre_q = static_cast<std::uint32_t>(port_field(centre_q.read(), 0, cb));
    g.sum = static_cast<std::uint32_t>(port_field(sum.read(), 0, sumb));
    g.count = static_cast<int>(port_field(count.read(), 0, cntb));
    if (o_.inject_fault == "centre_off_by_one" && !report.fault_injected && g.valid && cycle > 100) {
      g.centre_q += 1;
      report.fault_injected = true;
      report.fault_site = "cycle " + std::to_string(cycle) + ": centre + 1 LSB";
    }
    if (m != g) {
      auto str = [](const systemc::CentreProcessorPins& p) {
        std::ostringstream s;
        s << "valid " << p.valid << " centre_q " << p.centre_q << " sum " << p.sum << " n " << p.count;
        return s.str();
      };
      add(report, {"centre", -1, -1, -1, static_cast<std::uint64_t>(cycle), str(m), str(g)});
    }
    if (report.cycles >= o_.cycles) sc_core::sc_stop();
  }

  CosimOptions o_;
  systemc::CentreProcessorKernel kernel_;
  std::mt19937_64 rng_;
  long long edges_ = 0;
  int stream_left_ = 0, gap_left_ = 0, streams_ = 0;
  systemc::CentreProcessorPins e_;  // the kernel's pins of this cycle (trace)
};

// ---------------- multisampling_sequencer ----------------

class SequencerTop : public sc_core::sc_module {
 public:
  sc_core::sc_clock clk;
  sc_core::sc_signal<bool> rst{"rst", true};
  Vmultisampling_sequencer_small rtl{"rtl"};
  sc_core::sc_signal<PortData<decltype(rtl.phase_o)>> phase{"phase"};
  sc_core::sc_signal<bool> pix_reset{"pix_reset"}, latch{"latch"}, search_start{"search_start"},
      frame_done{"frame_done"};
  sc_core::sc_signal<PortData<decltype(rtl.sampling_o)>> sampling{"sampling"};
  sc_core::sc_signal<PortData<decltype(rtl.frame_o)>> frame{"frame"};

  SC_HAS_PROCESS(SequencerTop);
  SequencerTop(sc_core::sc_module_name n, const CosimOptions& o, sc_core::sc_time period)
      : sc_core::sc_module(n),
        clk("clk", period),
        o_(o),
        kernel_(small_config().timing, small_config().multisampling.samplings),
        rng_(o.seed) {
    rtl.clk(clk);
    rtl.rst(rst);
    rtl.phase_o(phase);
    rtl.pix_reset_o(pix_reset);
    rtl.latch_o(latch);
    rtl.search_start_o(search_start);
    rtl.frame_done_o(frame_done);
    rtl.sampling_o(sampling);
    rtl.frame_o(frame);
    report.target = "multisampling_sequencer";
    for (int p = 0; p < systemc::kReadoutPhases; ++p)
      phases_.push_back({p, systemc::readout_phase_name(static_cast<systemc::ReadoutPhase>(p))});
    SC_METHOD(on_posedge);
    sensitive << clk.posedge_event();
    dont_initialize();
    SC_METHOD(on_negedge);
    sensitive << clk.negedge_event();
    dont_initialize();
  }
  CosimReport report;

  // The kernel's pins of every cycle beside the RTL's (tb/common/cosim_run.h), as compared.
  void trace_expected(systemc::Waveform& w) {
    w.add(e_phase_, "sequencer", "phase", phases_);
    w.add(e_.pix_reset, "sequencer", "pix_reset");
    w.add(e_.latch, "sequencer", "latch");
    w.add(e_.search_start, "sequencer", "search_start");
    w.add(e_.frame_done, "sequencer", "frame_done");
    w.add(e_.sampling, "sequencer", "sampling");
    w.add(e_frame_, "sequencer", "frame");
  }

 private:
  void on_posedge() {
    const long long e = edges_++;
    if (e < kResetEdges - 1) return;
    kernel_.tick(e == kResetEdges - 1 || rst.read());
    // A reset pulse now and then (about once per 20 frame accesses), anywhere in the schedule.
    const bool pulse = std::uniform_int_distribution<long long>(0, 20 * kernel_.frame_cycles())(rng_) == 0;
    rst.write(pulse);
    if (pulse) CosimScoreboard(report).count("sequencer");
  }

  void on_negedge() {
    const long long period = edges_ - 1;
    if (period < kResetEdges - 1) return;
    const long long cycle = period - (kResetEdges - 1);
    report.cycles = static_cast<std::uint64_t>(cycle + 1);
    const int sb = clog2(small_config().multisampling.samplings + 1);
    systemc::MultisamplingSequencerPins m = kernel_.pins();
    m.frame &= 0xffffffffULL;
    e_ = m;
    e_phase_ = static_cast<int>(m.phase);
    e_frame_ = static_cast<long long>(m.frame);
    systemc::MultisamplingSequencerPins g;
    g.phase = static_cast<systemc::ReadoutPhase>(port_field(phase.read(), 0, 3));
    g.pix_reset = pix_reset.read();
    g.latch = latch.read();
    g.search_start = search_start.read();
    g.frame_done = frame_done.read();
    g.sampling = static_cast<int>(port_field(sampling.read(), 0, sb));
    g.frame = port_field(frame.read(), 0, 32);
    // Fault: the RTL's search start seen one cycle late, once.
    if (o_.inject_fault == "search_start_late" && cycle > 50) {
      if (!report.fault_injected && g.search_start) {
        g.search_start = false;
        late_ = true;
        report.fault_injected = true;
        report.fault_site = "frame " + std::to_string(g.frame) + " cycle " + std::to_string(cycle) +
                            ": search_start delayed by one cycle";
      } else if (late_) {
        g.search_start = true;
        late_ = false;
      }
    }
    // Strobes are the transactions: each search start, frame end and reset phase start.
    if (m.search_start || m.frame_done) CosimScoreboard(report).count("sequencer");
    if (!(m == g)) {
      auto str = [](const systemc::MultisamplingSequencerPins& p) {
        std::ostringstream s;
        s << "phase " << systemc::readout_phase_name(p.phase) << " pix_reset " << p.pix_reset << " latch " << p.latch
          << " search_start " << p.search_start << " frame_done " << p.frame_done << " sampling " << p.sampling
          << " frame " << p.frame;
        return s.str();
      };
      add(report,
          {"sequencer", static_cast<long long>(m.frame), -1, -1, static_cast<std::uint64_t>(cycle), str(m), str(g)});
    }
    if (report.cycles >= o_.cycles) sc_core::sc_stop();
  }

  CosimOptions o_;
  systemc::MultisamplingSequencerKernel kernel_;
  std::mt19937_64 rng_;
  long long edges_ = 0;
  bool late_ = false;
  // The kernel's pins of this cycle (trace): phase and frame as traceable integers.
  systemc::MultisamplingSequencerPins e_;
  int e_phase_ = 0;
  long long e_frame_ = 0;
  systemc::Waveform::ValueNames phases_;
};

template <class Top>
CosimReport run_block(const CosimOptions& o) {
  VerilatedContext* ctx = cosim_verilator_context(o);
  const sc_core::sc_time period(1.0 / FrameTimingConfig{}.clock_Hz, sc_core::SC_SEC);
  Top top("cosim", o, period);
  run_top(top, o, period, static_cast<long long>(o.cycles) + 2);
  CosimReport r = top.report;
  r.rtl_assertions_failed = ctx->gotError() ? 1 : 0;
  if (r.rtl_assertions_failed) add(r, rtl_assertion_mismatch(r.cycles));
  r.sc_errors = static_cast<int>(sc_core::sc_report_handler::get_count(sc_core::SC_ERROR));
  return r;
}

}  // namespace

CosimReport run_centre_processor_cosim(const CosimOptions& options) { return run_block<CentreTop>(options); }
CosimReport run_multisampling_sequencer_cosim(const CosimOptions& options) { return run_block<SequencerTop>(options); }

}  // namespace rangesim::tb
