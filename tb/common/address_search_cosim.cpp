// Co-simulation harness of address_search: see address_search_cosim.h.
//
// Timing: all outputs of both views change only just after a rising edge, so one SC_METHOD on
// the falling edge samples both sides mid-cycle (no delta races). The stimulus drives right
// after a rising edge and follows a fixed schedule computed from the row itself (never from the
// DUT outputs), so both sides get the identical input sequence even when they disagree.
#include "tb/common/address_search_cosim.h"

#include <verilated.h>
#include <verilated_vcd_sc.h>

#include <memory>
#include <random>
#include <sstream>
#include <tuple>
#include <systemc>
#include <type_traits>
#include <utility>

#include "Vaddress_search.h"
#include "Vaddress_search_small.h"
#include "core/ls_conventional/config.h"
#include "tb/common/address_search_stimulus.h"
#include "tb/common/cosim_coverage.h"
#include "tb/common/cosim_run.h"
#include "tb/common/cosim_scoreboard.h"
#include "tb/common/instance_preset.h"
#include "systemc/common/address_search.h"
#include "tb/common/cosim_target.h"  // kKeptMismatches

namespace rangesim::tb {
namespace {

using rangesim::systemc::ActivationRow;
using rangesim::systemc::AddressSearchPins;

constexpr const char* kMsgType = "rangesim/cosim/address_search";
constexpr int kResetCycles = 3;  // rst high; before its first edge the RTL state is random

// ActivationRow -> the verilated act_i port type (uint32_t up to 32 bits, sc_bv above 64).
void to_port(const ActivationRow& row, std::uint32_t& v) {
  v = row.words().empty() ? 0U : static_cast<std::uint32_t>(row.words()[0]);
}
[[maybe_unused]] void to_port(const ActivationRow& row, std::uint64_t& v) {
  v = row.words().empty() ? 0U : row.words()[0];
}
template <int W>
void to_port(const ActivationRow& row, sc_dt::sc_bv<W>& v) {
  for (int c = 0; c < W; ++c) v[c] = row.test(c);
}

struct Txn {
  int frame = 0;
  int row = 0;
  std::string kind;  // "left address", "right address", "done (found)"
  int value = 0;
  long long cycle = 0;
};

// One side's pins -> transactions (deserialises the bit stream).
class StreamMonitor {
 public:
  explicit StreamMonitor(int address_bits) : address_bits_(address_bits) {}
  int operations_done() const { return operations_done_; }
  int stream_bit_index() const { return nbits_; }  // index of the next stream bit

  void observe(const AddressSearchPins& p, long long cycle, std::pair<int, int> tag, std::vector<Txn>& out) {
    if (p.addr_valid) {
      bits_ = (bits_ << 1) | (p.addr_bit ? 1U : 0U);
      ++nbits_;
      const unsigned mask = (1U << address_bits_) - 1;
      if (nbits_ == address_bits_)
        out.push_back({tag.first, tag.second, "left address", static_cast<int>(bits_ & mask), cycle});
      if (nbits_ == 2 * address_bits_)
        out.push_back({tag.first, tag.second, "right address", static_cast<int>(bits_ & mask), cycle});
    }
    if (p.done) {
      out.push_back({tag.first, tag.second, "done (found)", p.found ? 1 : 0, cycle});
      bits_ = 0;
      nbits_ = 0;
      ++operations_done_;
    }
  }

 private:
  int address_bits_;
  unsigned bits_ = 0;        // stream bits so far, this operation
  int nbits_ = 0;            // how many
  int operations_done_ = 0;  // done_o pulses seen
};

template <class VTop>
class CosimTop : public sc_core::sc_module {
  // sc_in<T>::data_type of the verilated act_i port: uint32_t / uint64_t / sc_bv<N> by width.
  using ActPort = typename std::decay_t<decltype(std::declval<VTop&>().act_i)>::data_type;

 public:
  sc_core::sc_clock clk;
  sc_core::sc_signal<bool> rst{"rst", true};
  sc_core::sc_signal<bool> start{"start"};
  sc_core::sc_signal<ActPort> act_rtl{"act_rtl"};
  sc_core::sc_signal<ActivationRow> act_model{"act_model"};
  // Output pins, [0] = model, [1] = RTL.
  sc_core::sc_signal<bool> busy[2], found[2], addr_valid[2], addr_bit[2], done[2];

  VTop rtl{"rtl"};
  rangesim::systemc::AddressSearch model;

  SC_HAS_PROCESS(CosimTop);
  CosimTop(sc_core::sc_module_name name, const AddressSearchCosimOptions& options, const AddressSearchShape& params,
           sc_core::sc_time period)
      : sc_core::sc_module(name),
        clk("clk", period),
        model("model", AddressSearchConfig{params.columns, params.address_bits, 2}, params.search_cycles),
        options_(options),
        params_(params),
        rng_(options.seed),
        monitor_{StreamMonitor(params.address_bits), StreamMonitor(params.address_bits)} {
    operations_ = options.frames * options.rows_per_frame;
    model.clk_i(clk);
    model.rst_i(rst);
    model.start_i(start);
    model.act_i(act_model);
    model.busy_o(busy[0]);
    model.found_o(found[0]);
    model.addr_valid_o(addr_valid[0]);
    model.addr_bit_o(addr_bit[0]);
    model.done_o(done[0]);
    rtl.clk(clk);
    rtl.rst(rst);
    rtl.start_i(start);
    rtl.act_i(act_rtl);
    rtl.busy_o(busy[1]);
    rtl.found_o(found[1]);
    rtl.addr_valid_o(addr_valid[1]);
    rtl.addr_bit_o(addr_bit[1]);
    rtl.done_o(done[1]);
    act_model.write(ActivationRow(params.columns));  // correct width from the first cycle

    SC_THREAD(stimulus);
    sensitive << clk.posedge_event();
    SC_METHOD(monitor);
    sensitive << clk.negedge_event();
    dont_initialize();
  }

  // The model's pins beside the RTL's in the trace (tb/common/cosim_run.h), as compared.
  void trace_expected(systemc::Waveform& w) {
    w.add(busy[0], "address_search", "busy");
    w.add(found[0], "address_search", "found");
    w.add(addr_valid[0], "address_search", "addr_valid");
    w.add(addr_bit[0], "address_search", "addr_bit");
    w.add(done[0], "address_search", "done");
  }

  AddressSearchCosimReport& report() { return report_; }
  int operations() const { return operations_; }

  void finish_report() {
    // Transactions one side produced and the other did not.
    for (int side = 0; side < 2; ++side) {
      for (const Txn& t : queue_[side]) {
        std::ostringstream s;
        s << "frame " << t.frame << " row " << t.row << " cycle " << t.cycle << ": " << (side == 0 ? "model" : "RTL")
          << " " << t.kind << " " << t.value << " has no counterpart";
        mismatch(s.str());
      }
    }
    report_.operations_done = monitor_[1].operations_done();
    report_.finished = monitor_[0].operations_done() == operations_ && monitor_[1].operations_done() == operations_;
  }

 private:
  std::pair<int, int> tag(int op) const { return {op / options_.rows_per_frame, op % options_.rows_per_frame}; }

  void drive(const ActivationRow& row) {
    ActPort v{};
    to_port(row, v);
    act_rtl.write(v);
    act_model.write(row);
  }

  // Fixed schedule: reset, then operations back to back (next start in the cycle after
  // done_o) with random idle gaps; act_i carries garbage outside the start cycle.
  void stimulus() {
    for (int i = 0; i < kResetCycles; ++i) wait();
    rst.write(false);
    std::uniform_int_distribution<int> gap(0, options_.max_gap_cycles);
    const rangesim::systemc::AddressSearchKernel& k = model.kernel();
    for (int op = 0; op < operations_; ++op) {
      for (int g = gap(rng_); g > 0; --g) wait();
      const ActivationRow row = random_address_search_row(params_.columns, rng_);
      start.write(true);
      drive(row);
      wait();  // end of the start cycle k = 0
      start.write(false);
      drive(random_address_search_row(params_.columns, rng_));  // must be ignored
      int cycles = k.operation_cycles(row.any());
      if (op == options_.restart_operation && options_.restart_cycle >= 1 && options_.restart_cycle <= cycles) {
        for (int i = 1; i < options_.restart_cycle; ++i, --cycles) wait();
        start.write(true);  // protocol violation: start while busy
        wait();
        --cycles;
        start.write(false);
      }
      for (; cycles > 0; --cycles) wait();  // now in cycle k = done + 1
    }
    for (int i = 0; i < 2; ++i) wait();
    sc_core::sc_stop();
  }

  void monitor() {
    const long long cycle = cycle_++;
    report_.cycles = cycle_;
    if (cycle < kResetCycles) return;  // RTL state is random until the reset edge
    AddressSearchPins p[2];
    for (int s = 0; s < 2; ++s) {
      p[s] = {busy[s].read(), found[s].read(), addr_valid[s].read(), addr_bit[s].read(), done[s].read()};
    }
    // Fault injection: corrupt what the scoreboard sees of the RTL stream.
    if (options_.fault_operation >= 0 && report_.fault_frame < 0 &&
        monitor_[1].operations_done() >= options_.fault_operation && p[1].addr_valid &&
        monitor_[1].stream_bit_index() == options_.fault_bit) {
      p[1].addr_bit = !p[1].addr_bit;
      std::tie(report_.fault_frame, report_.fault_row) = tag(monitor_[1].operations_done());
    }
    const std::pair<int, int> t = tag(monitor_[0].operations_done());
    compare_pins(p[0], p[1], cycle, t);
    for (int s = 0; s < 2; ++s) {
      monitor_[s].observe(p[s], cycle, tag(monitor_[s].operations_done()), queue_[s]);
    }
    while (!queue_[0].empty() && !queue_[1].empty()) {
      compare(queue_[0].front(), queue_[1].front());
      queue_[0].erase(queue_[0].begin());
      queue_[1].erase(queue_[1].begin());
    }
  }

  void compare_pins(const AddressSearchPins& e, const AddressSearchPins& g, long long cycle, std::pair<int, int> t) {
    const std::pair<const char*, std::pair<bool, bool>> pins[] = {{"busy_o", {e.busy, g.busy}},
                                                                  {"found_o", {e.found, g.found}},
                                                                  {"addr_valid_o", {e.addr_valid, g.addr_valid}},
                                                                  {"addr_bit_o", {e.addr_bit, g.addr_bit}},
                                                                  {"done_o", {e.done, g.done}}};
    for (const auto& [name, v] : pins) {
      if (v.first != v.second) {
        std::ostringstream s;
        s << "frame " << t.first << " row " << t.second << " cycle " << cycle << ": " << name << " expected " << v.first
          << " got " << v.second;
        mismatch(s.str());
      }
    }
  }

  void compare(const Txn& e, const Txn& g) {
    ++report_.transactions_compared;
    std::ostringstream s;
    s << "frame " << e.frame << " row " << e.row << " cycle " << e.cycle << ": ";
    if (e.kind != g.kind || e.frame != g.frame || e.row != g.row) {
      s << "expected " << e.kind << " " << e.value << ", got " << g.kind << " " << g.value << " (frame " << g.frame
        << " row " << g.row << " cycle " << g.cycle << ")";
    } else if (e.value != g.value) {
      s << e.kind << " expected " << e.value << " got " << g.value;
    } else if (e.cycle != g.cycle) {
      s << e.kind << " " << e.value << " came at cycle " << g.cycle;
    } else {
      return;
    }
    mismatch(s.str());
  }

  void mismatch(const std::string& what) {
    ++report_.mismatch_count;
    if (report_.mismatches.size() < kKeptMismatches) {
      report_.mismatches.push_back(what);
      SC_REPORT_ERROR(kMsgType, what.c_str());  // counted; set to display, not throw
    }
  }

  AddressSearchCosimOptions options_;
  AddressSearchShape params_;
  std::mt19937_64 rng_;        // stimulus
  int operations_ = 0;         // frames * rows_per_frame
  long long cycle_ = 0;        // cycles seen by the monitor
  StreamMonitor monitor_[2];   // [0] model, [1] RTL
  std::vector<Txn> queue_[2];  // transactions not yet compared
  AddressSearchCosimReport report_;
};

template <class VTop>
AddressSearchCosimReport run(const AddressSearchCosimOptions& options, const AddressSearchShape& params) {
  // Random initial state (the reset must clear everything that matters); a failing Verilog
  // assertion is reported, not an abort.
  VerilatedContext* ctx = cosim_verilator_context(options.seed, options.trace_path);
  sc_core::sc_report_handler::set_actions(kMsgType, sc_core::SC_ERROR, sc_core::SC_DISPLAY);

  const sc_core::sc_time period(1.0 / FrameTimingConfig{}.clock_Hz, sc_core::SC_SEC);
  CosimTop<VTop> top("cosim", options, params, period);
  const long long per_op = 1 + params.search_cycles + 2 * params.address_bits + options.max_gap_cycles;
  const long long limit = options.cycle_limit > 0 ? options.cycle_limit : kResetCycles + 10 + per_op * top.operations();
  run_cosim_top(top, options.trace_path, period, limit);  // bounded by the cycle limit

  top.finish_report();
  AddressSearchCosimReport r = top.report();
  r.rtl_assertion_failed = ctx->gotError();
  r.sc_errors = static_cast<int>(sc_core::sc_report_handler::get_count(sc_core::SC_ERROR));
  return r;
}

}  // namespace

AddressSearchShape address_search_shape(AddressSearchInstance instance) {
  const char* prefix = instance == AddressSearchInstance::Default ? "Vaddress_search" : "Vaddress_search_small";
  const LsConventionalConfig c = ls_conventional_from_params(instance_preset(prefix));
  return {prefix, c.search.columns, c.search.address_bits, c.timing.search_cycles};
}

AddressSearchCosimReport run_address_search_cosim(const AddressSearchCosimOptions& options) {
  switch (options.instance) {
    case AddressSearchInstance::Default: return run<Vaddress_search>(options, address_search_shape(options.instance));
    case AddressSearchInstance::Small: break;
  }
  return run<Vaddress_search_small>(options, address_search_shape(options.instance));
}

}  // namespace rangesim::tb
