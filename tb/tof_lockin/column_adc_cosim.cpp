// Co-simulation of rtl/tof_lockin/column_adc.sv against ColumnAdcKernel.
//
// The analog side (V_in against the ramp) is the testbench's: in every conversion cycle the
// falling-edge monitor reads the RTL's ramp DAC code c and drives cmp_i = V_in < (c + 1) LSB,
// which the RTL samples at the next rising edge. The reference is the kernel's transfer
// function code = floor(V / LSB) clipped to the range, plus the cycle schedule (ramp = cycle
// index, done_o in cycle conversion_cycles - 1, code valid from the next cycle).
#include <verilated.h>
#include <verilated_vcd_sc.h>

#include <cmath>
#include <fstream>
#include <memory>
#include <random>
#include <systemc>

#include "Vcolumn_adc.h"
#include "core/tof_lockin/config.h"
#include "systemc/tof_lockin/sensor_kernel.h"
#include "tb/common/cosim_run.h"
#include "tb/common/cosim_scoreboard.h"
#include "tb/tof_lockin/lockin_gate_generator_cosim.h"
#include "tb/tof_lockin/stimulus.h"

namespace rangesim::tb {
namespace {

using rangesim::systemc::lockin::ColumnAdcKernel;

constexpr const char* kMsgType = "rangesim/cosim/column_adc";
constexpr int kResetCycles = 3;

using Conversion = ColumnAdcConversion;

class AdcCosimTop : public sc_core::sc_module {
 public:
  sc_core::sc_clock clk;
  sc_core::sc_signal<bool> rst{"rst", true}, start{"start"}, cmp{"cmp"};
  sc_core::sc_signal<std::uint32_t> conv{"conv"}, bits{"bits"};
  sc_core::sc_signal<bool> busy{"busy"}, done{"done"};
  sc_core::sc_signal<std::uint32_t> ramp{"ramp"}, code{"code"};
  Vcolumn_adc rtl{"rtl"};

  SC_HAS_PROCESS(AdcCosimTop);
  AdcCosimTop(sc_core::sc_module_name name, const CosimOptions& o, CosimReport& report, const std::string& record_path,
              sc_core::sc_time period_time)
      : sc_core::sc_module(name), clk("clk", period_time), o_(o), r_(report), sb_(report, kMsgType), rng_(o.seed) {
    rtl.clk(clk);
    rtl.rst(rst);
    rtl.start_i(start);
    rtl.conversion_cycles_i(conv);
    rtl.bits_i(bits);
    rtl.cmp_i(cmp);
    rtl.busy_o(busy);
    rtl.ramp_o(ramp);
    rtl.done_o(done);
    rtl.code_o(code);
    bits.write(12);
    conv.write(4096);
    if (!record_path.empty()) record_.open(record_path);
    SC_THREAD(stimulus);
    sensitive << clk.posedge_event();
    SC_METHOD(monitor);
    sensitive << clk.negedge_event();
    dont_initialize();
  }

  // The kernel's view of every cycle beside the RTL's (tb/common/cosim_run.h): busy, ramp and
  // done as compared, and the expected code from the cycle it becomes valid.
  void trace_expected(systemc::Waveform& w) {
    w.add(e_busy_, "adc", "busy");
    w.add(e_ramp_, "adc", "ramp");
    w.add(e_done_, "adc", "done");
    w.add(e_code_, "adc", "code");
  }

 private:
  void stimulus() {
    for (int i = 0; i < kResetCycles; ++i) wait();
    rst.write(false);
    wait();  // the monitor follows the model from the first cycle out of reset
    std::uniform_int_distribution<int> gap(0, 2);
    while (true) {
      for (int g = gap(rng_); g > 0; --g) wait();
      const Conversion c = random_column_adc_conversion(rng_);
      conv.write(static_cast<std::uint32_t>(c.cfg.readout.adc_conversion_cycles));
      bits.write(static_cast<std::uint32_t>(c.cfg.readout.adc_bits));
      pending_ = c;
      start.write(true);
      wait();
      start.write(false);
      for (long long k = c.cfg.readout.adc_conversion_cycles; k > 0; --k) wait();
      if (cycle_ >= o_.cycles) break;
    }
    for (int i = 0; i < 3; ++i) wait();
    sc_core::sc_stop();
  }

  void monitor() {
    const std::uint64_t cycle = cycle_++;
    r_.cycles = cycle_;
    if (cycle >= kResetCycles) check(cycle);
    // The comparator for this cycle, from the DAC code the RTL shows now.
    // V < (ramp + 1) LSB, in the kernel's arithmetic (floor(V / LSB)): inputs on a code
    // boundary compare as the kernel rounds them.
    const double lsb = ColumnAdcKernel(cur_.cfg).lsb_V();
    const bool c = in_conv_ && std::floor(cur_.v_in / lsb) <= static_cast<double>(ramp.read());
    cmp.write(c);
    if (record_.is_open()) {
      // Inputs as sampled at the coming edge (cmp just written is read back next delta: use
      // the value computed) and this cycle's outputs.
      record_ << rst.read() << ' ' << start.read() << ' ' << conv.read() << ' ' << bits.read() << ' ' << c << ' '
              << busy.read() << ' ' << ramp.read() << ' ' << done.read() << ' ' << code.read() << '\n';
    }
    // Model state for the next cycle.
    if (in_conv_) {
      if (++k_ == cur_.cfg.readout.adc_conversion_cycles) in_conv_ = false, check_code_ = true;
    } else if (start.read() && !rst.read()) {
      cur_ = pending_;
      in_conv_ = true;
      k_ = 0;
    }
  }

  void check(std::uint64_t cycle) {
    const long long n = conversions_;
    if (check_code_) {
      check_code_ = false;
      const ColumnAdcKernel adc(cur_.cfg);
      long long got = code.read();
      if (o_.inject_fault == "adc_code_off_by_one" && n == 2) {
        got += got < adc.top_code() ? 1 : -1;
        r_.fault_injected = true;
        r_.fault_site = "conversion 2: RTL code_o off by one";
      }
      e_code_ = adc.code(cur_.v_in);
      sb_.expect("adc_code", n, -1, -1, cycle, e_code_, got);
      ++conversions_;
    }
    const bool e_busy = in_conv_;
    const long long top = (1LL << cur_.cfg.readout.adc_bits) - 1;
    e_busy_ = e_busy;
    e_ramp_ = in_conv_ ? std::min<long long>(k_, top) : 0;
    e_done_ = in_conv_ && k_ == cur_.cfg.readout.adc_conversion_cycles - 1;
    sb_.pin("busy_o", n, cycle, e_busy, busy.read());
    if (in_conv_) {
      sb_.pin("ramp_o", n, cycle, std::min<long long>(k_, top), static_cast<long long>(ramp.read()));
      const bool e_done = k_ == cur_.cfg.readout.adc_conversion_cycles - 1;
      if (e_done || done.read()) sb_.expect("conversion_end", n, -1, -1, cycle, e_done, done.read());
    } else {
      sb_.pin("done_o", n, cycle, false, done.read());
    }
  }

  CosimOptions o_;
  CosimReport& r_;
  CosimScoreboard sb_;
  std::mt19937_64 rng_;
  Conversion pending_, cur_;   // drawn by the stimulus / being converted
  bool in_conv_ = false;       // the model is converting in this cycle
  long long k_ = 0;            // its cycle within the conversion
  bool check_code_ = false;    // the code becomes valid in this cycle
  long long conversions_ = 0;  // conversions checked
  std::uint64_t cycle_ = 0;
  std::ofstream record_;
  // The kernel's view of this cycle (trace_expected).
  bool e_busy_ = false, e_done_ = false;
  long long e_ramp_ = 0, e_code_ = 0;
};

}  // namespace

CosimReport run_column_adc_cosim(const CosimOptions& o, const std::string& record) {
  CosimReport r;
  r.target = "column_adc";
  VerilatedContext* ctx = cosim_verilator_context(o);
  const sc_core::sc_time period(1.0 / TofLockinConfig{}.readout.clock_Hz, sc_core::SC_SEC);
  AdcCosimTop top("cosim", o, r, record, period);
  run_cosim_top(top, o.trace_path, period, o.cycles + 4200 + 100); // + one conversion
  finish_cosim_report(r, ctx);
  return r;
}

}  // namespace rangesim::tb
