// Co-simulation of rtl/tof_lockin/lockin_gate_generator.sv against LockinGateGeneratorKernel (tick by tick).
//
// Timing: stimulus drives right after a rising edge; one SC_METHOD on the falling edge samples
// the RTL pins, compares them with the kernel's state for this cycle, then advances the kernel
// exactly as the RTL will at the next rising edge (start() when idle and start_i is high,
// advance(1) when busy). The stimulus schedule comes from the drawn parameters only (never
// from DUT outputs), so both views see the same inputs even when they disagree.
#include <verilated.h>
#include <verilated_vcd_sc.h>

#include <cmath>
#include <fstream>
#include <memory>
#include <optional>
#include <random>
#include <systemc>

#include "Vlockin_gate_generator.h"
#include "core/tof_lockin/config.h"
#include "systemc/tof_lockin/sensor_kernel.h"
#include "tb/common/cosim_run.h"
#include "tb/common/cosim_scoreboard.h"
#include "tb/tof_lockin/lockin_gate_generator_cosim.h"
#include "tb/tof_lockin/stimulus.h"

namespace rangesim::tb {
namespace {

using rangesim::systemc::lockin::LockinGateGeneratorKernel;

constexpr const char* kMsgType = "rangesim/cosim/lockin_gate_generator";
constexpr int kResetCycles = 3;

struct Pins {
  bool busy, tx1, tx2, txd, light, last;
};

class GateCosimTop : public sc_core::sc_module {
 public:
  sc_core::sc_clock clk;
  sc_core::sc_signal<bool> rst{"rst", true}, start{"start"};
  sc_core::sc_signal<std::uint32_t> t0{"t0"}, period{"period"}, acc_n{"acc_n"};
  sc_core::sc_signal<bool> busy{"busy"}, tx1{"tx1"}, tx2{"tx2"}, txd{"txd"}, light{"light"}, last{"last"};
  sc_core::sc_signal<std::uint32_t> cycle{"cycle"}, accumulation{"accumulation"};
  Vlockin_gate_generator rtl{"rtl"};

  SC_HAS_PROCESS(GateCosimTop);
  GateCosimTop(sc_core::sc_module_name name, const CosimOptions& o, CosimReport& report, const std::string& record_path,
               sc_core::sc_time period_time)
      : sc_core::sc_module(name), clk("clk", period_time), o_(o), r_(report), sb_(report, kMsgType), rng_(o.seed) {
    rtl.clk(clk);
    rtl.rst(rst);
    rtl.start_i(start);
    rtl.t0_cycles_i(t0);
    rtl.period_cycles_i(period);
    rtl.accumulations_i(acc_n);
    rtl.busy_o(busy);
    rtl.tx1_o(tx1);
    rtl.tx2_o(tx2);
    rtl.txd_o(txd);
    rtl.light_o(light);
    rtl.last_o(last);
    rtl.cycle_o(cycle);
    rtl.accumulation_o(accumulation);
    if (!record_path.empty()) record_.open(record_path);
    SC_THREAD(stimulus);
    sensitive << clk.posedge_event();
    SC_METHOD(monitor);
    sensitive << clk.negedge_event();
    dont_initialize();
  }

  // The kernel's pins of every cycle beside the RTL's (tb/common/cosim_run.h), as compared.
  void trace_expected(systemc::Waveform& w) {
    w.add(e_.busy, "gates", "busy");
    w.add(e_.tx1, "gates", "tx1");
    w.add(e_.tx2, "gates", "tx2");
    w.add(e_.txd, "gates", "txd");
    w.add(e_.light, "gates", "light");
    w.add(e_.last, "gates", "last");
  }

  void finish() {
    // Edges one side produced and the other did not (the run ends between operations).
    for (std::size_t i = matched_; i < edges_[0].size() || i < edges_[1].size(); ++i) {
      const Edge* e = i < edges_[0].size() ? &edges_[0][i] : nullptr;
      const Edge* a = i < edges_[1].size() ? &edges_[1][i] : nullptr;
      sb_.mismatch("gate_edge", (e ? e : a)->op, -1, -1, (e ? e : a)->cycle, e ? e->text() : "none",
                   a ? a->text() : "none");
    }
  }

 private:
  struct Edge {
    long long op;
    const char* gate;
    bool rise;
    std::uint64_t cycle;
    std::string text() const { return std::string(gate) + (rise ? " rise" : " fall") + " @" + std::to_string(cycle); }
    bool operator==(const Edge& b) const {
      return op == b.op && std::string(gate) == b.gate && rise == b.rise && cycle == b.cycle;
    }
  };

  void stimulus() {
    for (int i = 0; i < kResetCycles; ++i) wait();
    rst.write(false);
    wait();  // the monitor follows the model from the first cycle out of reset
    std::uniform_int_distribution<int> gap(0, 3);
    while (true) {
      for (int g = gap(rng_); g > 0; --g) wait();
      const TofLockinConfig cfg = random_lockin_gate_generator_config(rng_);
      const LockinGateGeneratorKernel k(cfg);
      t0.write(static_cast<std::uint32_t>(k.t0_cycles()));
      period.write(static_cast<std::uint32_t>(k.period_cycles()));
      acc_n.write(static_cast<std::uint32_t>(k.accumulations()));
      pending_ = cfg;
      start.write(true);
      wait();
      start.write(false);
      const long long cycles = k.accumulations() * k.period_cycles();
      if (o_.inject_fault == "period_change_while_busy" && ops_started_ == 1) {
        // Protocol violation: T_rep shrinks below the running cycle counter mid-operation;
        // the RTL assertion a_cycle_in_period must fire (the scoreboard sees mismatches too).
        for (long long c = 0; c < k.period_cycles() - 1; ++c) wait();
        period.write(static_cast<std::uint32_t>(k.t0_cycles()) / 2 + 1);
        r_.fault_injected = true;
        r_.fault_site = "operation 1: period_cycles_i shrunk while busy";
        for (long long c = k.period_cycles() - 1; c < cycles; ++c) wait();
      } else {
        for (long long c = cycles; c > 0; --c) wait();
      }
      ++ops_started_;
      if (cycle_ >= o_.cycles) break;  // whole operations only
    }
    for (int i = 0; i < 2; ++i) wait();
    sc_core::sc_stop();
  }

  void monitor() {
    const std::uint64_t cycle = cycle_++;
    r_.cycles = cycle_;
    Pins a{busy.read(), tx1.read(), tx2.read(), txd.read(), light.read(), last.read()};
    if (record_.is_open()) {
      record_ << rst.read() << ' ' << start.read() << ' ' << t0.read() << ' ' << period.read() << ' ' << acc_n.read()
              << ' ' << a.busy << a.tx1 << a.tx2 << a.txd << a.light << a.last << '\n';
    }
    if (cycle < kResetCycles) return;  // random state until the reset edge
    Pins& e = e_;
    e = {false, false, false, false, false, false};
    if (kernel_ && !kernel_->done()) {
      e = {true,
           kernel_->tx1(),
           kernel_->tx2(),
           kernel_->txd(),
           kernel_->light(),
           kernel_->accumulation() == kernel_->accumulations() - 1 &&
               kernel_->cycle_in_period() == kernel_->period_cycles() - 1};
    }
    // Fault gate_shift: the scoreboard sees the RTL's TX2 one cycle late in the second
    // period of operation 1 (its edges move by one cycle).
    if (o_.inject_fault == "gate_shift" && kernel_ && op_ == 1 && !kernel_->done() &&
        kernel_->accumulation() == std::min<long long>(1, kernel_->accumulations() - 1)) {
      const bool late = prev_tx2_;
      prev_tx2_ = a.tx2;
      if (late != a.tx2 && !r_.fault_injected) {
        r_.fault_injected = true;
        r_.fault_site =
            "operation 1 accumulation " + std::to_string(kernel_->accumulation()) + ": RTL tx2_o delayed one cycle";
      }
      a.tx2 = late;
    } else {
      prev_tx2_ = a.tx2;
    }
    const long long op = op_;
    sb_.pin("busy_o", op, cycle, e.busy, a.busy);
    sb_.pin("tx1_o", op, cycle, e.tx1, a.tx1);
    sb_.pin("tx2_o", op, cycle, e.tx2, a.tx2);
    sb_.pin("txd_o", op, cycle, e.txd, a.txd);
    sb_.pin("light_o", op, cycle, e.light, a.light);
    sb_.pin("last_o", op, cycle, e.last, a.last);
    // Gate edges as ordered transactions (with the cycle: the spec is cycle-exact).
    const bool now[2][4] = {{e.tx1, e.tx2, e.txd, e.light}, {a.tx1, a.tx2, a.txd, a.light}};
    static const char* names[4] = {"tx1", "tx2", "txd", "light"};
    for (int s = 0; s < 2; ++s) {
      for (int g = 0; g < 4; ++g) {
        if (now[s][g] != was_[s][g]) edges_[s].push_back({op, names[g], now[s][g], cycle});
        was_[s][g] = now[s][g];
      }
    }
    for (; matched_ < edges_[0].size() && matched_ < edges_[1].size(); ++matched_) {
      const Edge& x = edges_[0][matched_];
      const Edge& y = edges_[1][matched_];
      sb_.expect("gate_edge", x.op, -1, -1, x.cycle, x.text(), y.text());
    }
    // Advance the model as the RTL does at the coming edge.
    if (kernel_ && !kernel_->done()) {
      kernel_->advance(1);
      if (kernel_->done()) ++op_;
    } else if (start.read() && !rst.read()) {
      kernel_.emplace(pending_);
      kernel_->start();
    }
  }

  CosimOptions o_;
  CosimReport& r_;
  CosimScoreboard sb_;
  std::mt19937_64 rng_;                              // stimulus
  TofLockinConfig pending_;                          // parameters of the operation being started
  std::optional<LockinGateGeneratorKernel> kernel_;  // reference for the current operation
  std::uint64_t cycle_ = 0;                          // cycles seen by the monitor
  long long op_ = 0;                                 // operations completed by the model
  long long ops_started_ = 0;
  bool prev_tx2_ = false;                             // RTL tx2 of the previous cycle (fault injection)
  bool was_[2][4] = {};                               // gate levels of the previous cycle, model / RTL
  std::vector<Edge> edges_[2];                        // gate edges, model / RTL
  std::size_t matched_ = 0;                           // edges compared so far
  std::ofstream record_;                              // Icarus replay file
  Pins e_{false, false, false, false, false, false};  // the kernel's pins of this cycle (trace)
};

}  // namespace

CosimReport run_lockin_gate_generator_cosim(const CosimOptions& o, const std::string& record) {
  CosimReport r;
  r.target = "lockin_gate_generator";
  VerilatedContext* ctx = cosim_verilator_context(o);
  const sc_core::sc_time period(1.0 / TofLockinConfig{}.gates.clock_Hz, sc_core::SC_SEC);
  GateCosimTop top("cosim", o, r, record, period);
  // Bounded: the requested cycles plus the longest operation (64 x 320) and slack.
  run_cosim_top(top, o.trace_path, period, o.cycles + 64 * 320 + 100);
  top.finish();
  finish_cosim_report(r, ctx);
  return r;
}

}  // namespace rangesim::tb
