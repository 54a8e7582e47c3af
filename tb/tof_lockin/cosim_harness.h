#pragma once
// Co-simulation harness of the tof-lockin readout, rtl/tof_lockin/tof_lockin_readout.sv (the frame
// sequencer with its lockin_gate_generator, and one column_adc per simulated column and tap),
// against TofLockinSensorKernel in tick mode (one step = one clock cycle; the co-simulation runs
// gate and readout phases on one clock, the schedule counts cycles). Templated on the verilated
// class: one harness for the built-in instance (tb/tof_lockin/cosim.cpp) and the instances
// verilated at run time for a preset or a user's RTL (tb/common/rtl_build.h).
//
// Per cycle: phase, gate pins, light, row, frame and busy of the sequencer against the kernel's
// state before its step, and in conversion cycle c every ADC's ramp code min(c, 2^bits - 1).
// Transactions: phase boundaries (phase, cycle), the ADC code of every (frame, row, column, tap)
// when the row's conversion ends, and the kernel's ADC inputs against a look-ahead run. Golden
// checks: eq. 2.25 applied to the RTL codes (golden::max_range_m) gives the kernel's range of every
// pixel and range map, NaN where the kernel rejects the pixel.
//
// The analog side: the ADC inputs of a row are known only at the end of the kernel's
// conversion, so a look-ahead kernel with the same configuration and seed runs the whole
// sequence first (deterministic noise streams) and drives the comparators.
#include <verilated.h>
#include <verilated_vcd_sc.h>

#include <cmath>
#include <memory>
#include <random>
#include <sstream>
#include <systemc>
#include <vector>

#include "core/params.h"
#include "core/tof_lockin/config.h"
#include "golden/tof_lockin/pulse_timing.h"
#include "systemc/tof_lockin/sensor_kernel.h"
#include "tb/common/cosim_child.h"
#include "tb/common/cosim_ports.h"
#include "tb/common/cosim_run.h"
#include "tb/common/cosim_scoreboard.h"
#include "tb/tof_lockin/stimulus.h"
#include "tb/tof_lockin/verilog_parameters.h"

namespace rangesim::tb {
namespace tof_lockin_harness {

// The clock-level model this harness drives (no using-directive in a header).
using rangesim::systemc::lockin::ColumnAdcKernel;
using rangesim::systemc::lockin::LockinGateGeneratorKernel;
using rangesim::systemc::lockin::LockinPhase;
using rangesim::systemc::lockin::phase_name;
using rangesim::systemc::lockin::TofLockinSensorKernel;

constexpr const char* kMsgType = "rangesim/cosim/tof-lockin";
constexpr int kResetCycles = 3;

struct Event {
  long long frame, row;
  int phase;
  std::uint64_t cycle;
  bool operator==(const Event& b) const {
    return phase == b.phase && cycle == b.cycle;  // frame and row are context
  }
};
inline std::ostream& operator<<(std::ostream& os, const Event& e) {
  return os << phase_name(static_cast<LockinPhase>(e.phase)) << " from cycle " << e.cycle;
}

// The model's pins of the current cycle as the scoreboard compares them (traced under
// "expected" by trace_expected()).
struct Expected {
  int phase = 0;
  bool busy = false, tx1 = false, tx2 = false, txd = false, light = false;
  int row = 0;
  long long frame = 0;
  long long ramp = 0;  // every ADC's ramp code (0 outside a conversion)
};

// VTop: rtl/tof_lockin/tof_lockin_readout.sv verilated with the parameters of
// tof_lockin_rtl_shape() (tb/tof_lockin/verilog_parameters.h): its ADC fields are `adc_bits` wide
// and it has `adc_channels` ADCs, channel 2 column + tap.
template <class VTop>
class LockinCosimTop : public sc_core::sc_module {
  template <class P>
  using Sig = sc_core::sc_signal<PortData<P>>;

 public:
  sc_core::sc_clock clk;
  VTop rtl{"rtl"};
  sc_core::sc_signal<bool> rst{"rst", true}, start{"start"}, ambient{"ambient"};
  sc_core::sc_signal<std::uint32_t> t0{"t0"}, period{"period"}, acc_n{"acc_n"}, rows{"rows"}, conv{"conv"},
      outc{"outc"}, frames{"frames"}, bits{"bits"};
  sc_core::sc_signal<bool> busy{"busy"}, tx1{"tx1"}, tx2{"tx2"}, txd{"txd"}, light{"light"}, adc_start{"adc_start"},
      frame_done{"frame_done"};
  sc_core::sc_signal<std::uint32_t> phase{"phase"}, row{"row"}, frame{"frame"};
  Sig<decltype(rtl.cmp_i)> cmp{"cmp"};
  Sig<decltype(rtl.adc_busy_o)> adc_busy{"adc_busy"};
  Sig<decltype(rtl.adc_done_o)> adc_done{"adc_done"};
  Sig<decltype(rtl.ramp_o)> ramp{"ramp"};
  Sig<decltype(rtl.code_o)> code{"code"};

  SC_HAS_PROCESS(LockinCosimTop);
  LockinCosimTop(sc_core::sc_module_name name, const CosimOptions& o, CosimReport& report, TofLockinSetup setup,
                 const TofLockinRtlShape& shape, sc_core::sc_time period_time)
      : sc_core::sc_module(name),
        clk("clk", period_time),
        o_(o),
        r_(report),
        sb_(report, kMsgType),
        s_(std::move(setup)),
        shape_(shape),
        kernel_(s_.cfg, s_.sim, s_.cfg.pixel.rows, s_.cfg.pixel.columns, s_.stim, s_.frames),
        ahead_(s_.cfg, s_.sim, s_.cfg.pixel.rows, s_.cfg.pixel.columns, s_.stim, s_.frames),
        adc_(s_.cfg) {
    ahead_.run();
    rtl.clk(clk);
    rtl.rst(rst);
    rtl.start_i(start);
    rtl.t0_cycles_i(t0);
    rtl.period_cycles_i(period);
    rtl.accumulations_i(acc_n);
    rtl.rows_i(rows);
    rtl.conversion_cycles_i(conv);
    rtl.output_cycles_i(outc);
    rtl.frames_i(frames);
    rtl.ambient_i(ambient);
    rtl.bits_i(bits);
    rtl.cmp_i(cmp);
    rtl.busy_o(busy);
    rtl.phase_o(phase);
    rtl.tx1_o(tx1);
    rtl.tx2_o(tx2);
    rtl.txd_o(txd);
    rtl.light_o(light);
    rtl.adc_start_o(adc_start);
    rtl.row_o(row);
    rtl.frame_o(frame);
    rtl.frame_done_o(frame_done);
    rtl.adc_busy_o(adc_busy);
    rtl.adc_done_o(adc_done);
    rtl.ramp_o(ramp);
    rtl.code_o(code);
    channels_ = 2 * s_.cfg.pixel.columns;
    expected_code_.assign(static_cast<std::size_t>(channels_), 0);
    rtl_codes_.assign(static_cast<std::size_t>(s_.frames) * s_.cfg.pixel.rows * channels_, 0);
    SC_THREAD(stimulus);
    sensitive << clk.posedge_event();
    SC_METHOD(monitor);
    sensitive << clk.negedge_event();
    dont_initialize();
  }

  // The clock-level model's pins of every cycle, beside the RTL's in the trace
  // (tb/common/cosim_run.h), as the scoreboard compares them at the falling edge; each ADC
  // channel's expected code from the cycle its conversion ends.
  void trace_expected(systemc::Waveform& w) {
    systemc::Waveform::ValueNames phases;
    for (int p = 0; p <= static_cast<int>(LockinPhase::Output); ++p)
      phases.push_back({p, phase_name(static_cast<LockinPhase>(p))});
    w.add(e_.phase, "sequencer", "phase", phases);
    w.add(e_.busy, "sequencer", "busy");
    w.add(e_.tx1, "sequencer", "tx1");
    w.add(e_.tx2, "sequencer", "tx2");
    w.add(e_.txd, "sequencer", "txd");
    w.add(e_.light, "sequencer", "light");
    w.add(e_.row, "sequencer", "row");
    w.add(e_.frame, "sequencer", "frame");
    for (int i = 0; i < channels_; ++i) {
      w.add(e_.ramp, "adc" + std::to_string(i), "ramp");
      w.add(expected_code_[static_cast<std::size_t>(i)], "adc" + std::to_string(i), "code");
    }
  }

  long long cycle_bound() const {
    const TofLockinConfig& c = s_.cfg;
    return 10 + s_.frames * (c.gates.accumulations_per_frame * gate_period_cycles(c) +
                             c.pixel.rows * (c.readout.adc_conversion_cycles + c.readout.output_cycles_per_row));
  }

  // Unmatched phase boundaries, then eq. 2.25 on the RTL codes against the kernel's ranges.
  void finish() {
    for (std::size_t i = matched_; i < ev_[0].size() || i < ev_[1].size(); ++i) {
      const Event* e = i < ev_[0].size() ? &ev_[0][i] : nullptr;
      const Event* a = i < ev_[1].size() ? &ev_[1][i] : nullptr;
      std::ostringstream es, as;
      if (e)
        es << *e;
      else
        es << "none";
      if (a)
        as << *a;
      else
        as << "none";
      const Event& w = e ? *e : *a;
      sb_.mismatch("phase_boundary", w.frame, w.row, -1, w.cycle, es.str(), as.str());
    }
    const TofLockinConfig& c = s_.cfg;
    const double lsb = adc_.lsb_V();
    for (long long m = 0; m < kernel_.range_maps(); ++m) {
      const long long f = c.readout.ambient_subtraction ? 2 * m : m;
      for (int rr = 0; rr < c.pixel.rows; ++rr) {
        for (int cc = 0; cc < c.pixel.columns; ++cc) {
          double v[2];
          bool sat = false;
          for (int k = 0; k < 2; ++k) {
            const long long x = rtl_code(f, rr, cc, k);
            sat = sat || x == adc_.top_code();
            v[k] = static_cast<double>(x) * lsb - c.readout.offset_calibration_V;
            if (c.readout.ambient_subtraction) v[k] -= static_cast<double>(rtl_code(f + 1, rr, cc, k)) * lsb;
          }
          const double sum = v[0] + v[1];
          const bool ok = !sat && sum > 0.0 && sum >= c.readout.detection_threshold_V * (1.0 - 1e-9);
          const double range = ok ? golden::max_range_m(c.source) * v[1] / sum : std::nan("");
          const double want = kernel_.range_m(m, rr, cc);
          ++r_.golden_checks;
          const bool same = (std::isnan(range) && std::isnan(want)) || range == want;
          if (!same) {
            sb_.mismatch("range_m (eq. 2.25 on RTL codes)", f, rr, cc, cycle_, std::to_string(want),
                         std::to_string(range));
          }
        }
      }
    }
  }

 private:
  std::uint32_t& rtl_code(long long f, int rr, int cc, int k) {
    return rtl_codes_[(static_cast<std::size_t>(f) * s_.cfg.pixel.rows + rr) * channels_ + 2 * cc + k];
  }
  long long channel_field(const PortData<decltype(rtl.code_o)>& v, int i) const {
    return static_cast<long long>(port_field(v, i * shape_.adc_bits, shape_.adc_bits));
  }

  void stimulus() {
    const LockinGateGeneratorKernel g(s_.cfg);
    t0.write(static_cast<std::uint32_t>(g.t0_cycles()));
    period.write(static_cast<std::uint32_t>(g.period_cycles()));
    acc_n.write(static_cast<std::uint32_t>(g.accumulations()));
    rows.write(static_cast<std::uint32_t>(s_.cfg.pixel.rows));
    conv.write(static_cast<std::uint32_t>(s_.cfg.readout.adc_conversion_cycles));
    outc.write(static_cast<std::uint32_t>(s_.cfg.readout.output_cycles_per_row));
    frames.write(static_cast<std::uint32_t>(s_.frames));
    bits.write(static_cast<std::uint32_t>(s_.cfg.readout.adc_bits));
    ambient.write(s_.cfg.readout.ambient_subtraction);
    for (int i = 0; i < kResetCycles; ++i) wait();
    rst.write(false);
    wait();
    start.write(true);
    wait();
    start.write(false);
    while (!kernel_.done()) wait();
    for (int i = 0; i < 3; ++i) wait();
    sc_core::sc_stop();
  }

  void monitor() {
    const std::uint64_t cycle = cycle_++;
    r_.cycles = cycle_;
    if (cycle < kResetCycles) return;
    // Expected state of this cycle: the kernel before its step (Idle at a frame start means
    // the step begins the frame: PHASE1, cycle 0).
    const bool run = started_ && !kernel_.done();
    LockinPhase ph = run ? kernel_.phase() : LockinPhase::Idle;
    const bool fresh = run && ph == LockinPhase::Idle;
    if (fresh) ph = LockinPhase::Phase1;
    const bool gating = ph == LockinPhase::Phase1 || ph == LockinPhase::Phase2 || ph == LockinPhase::Phase3;
    const bool e_tx1 = fresh || (gating && kernel_.gates().tx1());
    const bool e_tx2 = !fresh && gating && kernel_.gates().tx2();
    const bool e_txd = !fresh && gating && kernel_.gates().txd();
    const long long f = run ? kernel_.frame() : -1;
    const long long rrow = gating || !run ? 0 : kernel_.readout_row();
    const bool converting = run && ph == LockinPhase::AdcConversion;
    conversion_cycle_ = !converting ? -1 : prev_phase_ == LockinPhase::AdcConversion ? conversion_cycle_ + 1 : 0;
    e_ = {static_cast<int>(ph),
          run,
          e_tx1,
          e_tx2,
          e_txd,
          e_tx1 && run && kernel_.led_on(),
          static_cast<int>(rrow),
          run ? f : 0,
          converting ? std::min<long long>(conversion_cycle_, adc_.top_code()) : 0};

    bool a_tx2 = tx2.read();
    if (o_.inject_fault == "gate_shift" && run && gating && !fresh && f == 0 &&
        kernel_.gates().accumulation() == std::min<long long>(1, kernel_.gates().accumulations() - 1)) {
      const bool late = prev_tx2_;
      if (late != a_tx2 && !r_.fault_injected) {
        r_.fault_injected = true;
        r_.fault_site =
            "frame 0 accumulation " + std::to_string(kernel_.gates().accumulation()) + ": RTL tx2_o delayed one cycle";
      }
      prev_tx2_ = a_tx2;
      a_tx2 = late;
    } else {
      prev_tx2_ = a_tx2;
    }
    sb_.pin("busy_o", f, cycle, run, busy.read());
    sb_.pin("phase_o", f, cycle, static_cast<int>(ph), static_cast<int>(phase.read()));
    sb_.pin("tx1_o", f, cycle, e_tx1, tx1.read());
    sb_.pin("tx2_o", f, cycle, e_tx2, a_tx2);
    sb_.pin("txd_o", f, cycle, e_txd, txd.read());
    sb_.pin("light_o", f, cycle, e_.light, light.read());
    if (run) {
      sb_.pin("row_o", f, cycle, rrow, static_cast<long long>(row.read()));
      sb_.pin("frame_o", f, cycle, f, static_cast<long long>(frame.read()));
    }
    // Phase boundaries as transactions (the RTL phase with the gate pins as seen, so a shifted
    // gate edge shows here too).
    const int ph_rtl = phase.read() >= 1 && phase.read() <= 3 ? (tx1.read() ? 1
                                                                 : a_tx2    ? 2
                                                                            : 3)
                                                              : static_cast<int>(phase.read());
    const int now[2] = {static_cast<int>(ph), ph_rtl};
    for (int s = 0; s < 2; ++s) {
      if (now[s] != last_phase_[s]) {
        ev_[s].push_back({s == 0 ? f : static_cast<long long>(frame.read()),
                          s == 0 ? rrow : static_cast<long long>(row.read()), now[s], cycle});
      }
      last_phase_[s] = now[s];
    }
    for (; matched_ < ev_[0].size() && matched_ < ev_[1].size(); ++matched_) {
      const Event& e = ev_[0][matched_];
      sb_.expect("phase_boundary", e.frame, e.row, -1, cycle, e, ev_[1][matched_]);
    }
    // ADC codes of the row whose conversion ended in the previous cycle.
    if (run && ph == LockinPhase::Output && prev_phase_ == LockinPhase::AdcConversion) check_codes(cycle);
    prev_phase_ = ph;
    if (converting) check_ramps(f, static_cast<int>(rrow), cycle);
    drive_comparators(converting, f, static_cast<int>(rrow));
    // Advance the model as the RTL does at the coming edge.
    if (run) kernel_.step();
    if (!started_ && start.read() && !rst.read()) started_ = true;
  }

  // Comparators for this cycle (the analog side: the look-ahead's inputs of this row):
  // V < (ramp + 1) LSB, in the kernel's own arithmetic (floor(V / LSB)) so that inputs on a
  // code boundary compare as the kernel rounds them. Channels beyond the array see 0.
  void drive_comparators(bool converting, long long f, int rrow) {
    const double lsb = adc_.lsb_V();
    const PortData<decltype(rtl.ramp_o)> ramps = ramp.read();
    std::vector<std::uint32_t> words(static_cast<std::size_t>((shape_.adc_channels + 31) / 32), 0U);
    for (int i = 0; i < channels_; ++i) {
      const double v = converting ? ahead_.adc_input_V(f, rrow, i / 2, i % 2) : 0.0;
      if (std::floor(v / lsb) <= static_cast<double>(channel_field(ramps, i)))
        words[static_cast<std::size_t>(i / 32)] |= 1U << (i % 32);
    }
    PortData<decltype(rtl.cmp_i)> c{};
    port_from_words(words, c);
    cmp.write(c);
  }

  // Every ADC's ramp code in cycle c of a conversion: min(c, 2^bits - 1) (docs/rtl-contract.md).
  void check_ramps(long long f, int rrow, std::uint64_t cycle) {
    const PortData<decltype(rtl.ramp_o)> ramps = ramp.read();
    for (int i = 0; i < channels_; ++i) {
      const long long got = channel_field(ramps, i);
      if (got != e_.ramp)
        sb_.mismatch(i % 2 == 0 ? "ramp_o tap1" : "ramp_o tap2", f, rrow, i / 2, cycle, std::to_string(e_.ramp),
                     std::to_string(got));
    }
  }

  void check_codes(std::uint64_t cycle) {
    const long long f = kernel_.frame();
    const int rr = kernel_.readout_row();
    const PortData<decltype(rtl.code_o)> codes = code.read();
    for (int i = 0; i < channels_; ++i) {
      const int cc = i / 2, k = i % 2;
      long long got = channel_field(codes, i);
      if (o_.inject_fault == "adc_code_off_by_one" && f == 0 && rr == 1 && i == 0) {
        got += got < adc_.top_code() ? 1 : -1;
        r_.fault_injected = true;
        r_.fault_site = "frame 0 row 1 column 0 tap 1: RTL code_o off by one";
      }
      rtl_code(f, rr, cc, k) = static_cast<std::uint32_t>(got);
      const long long want = kernel_.code(f, rr, cc, k);
      expected_code_[static_cast<std::size_t>(i)] = want;
      sb_.expect(k == 0 ? "adc_code tap1" : "adc_code tap2", f, rr, cc, cycle, want, got);
      sb_.expect("adc_input_V (tick vs look-ahead)", f, rr, cc, cycle, kernel_.adc_input_V(f, rr, cc, k),
                 ahead_.adc_input_V(f, rr, cc, k));
    }
  }

  CosimOptions o_;
  CosimReport& r_;
  CosimScoreboard sb_;
  TofLockinSetup s_;
  TofLockinRtlShape shape_;
  TofLockinSensorKernel kernel_;  // reference, stepped once per cycle
  TofLockinSensorKernel ahead_;   // same run, finished up front (drives the comparators)
  ColumnAdcKernel adc_;
  int channels_ = 0;                 // ADC channels in use: 2 x columns
  long long conversion_cycle_ = -1;  // cycle of the current conversion (-1: none)
  bool started_ = false;             // start_i seen: the kernel steps from the next cycle
  std::uint64_t cycle_ = 0;
  bool prev_tx2_ = false;  // RTL tx2 of the previous cycle (fault injection)
  LockinPhase prev_phase_ = LockinPhase::Idle;
  int last_phase_[2] = {0, 0};  // phase of the previous cycle, model / RTL
  std::vector<Event> ev_[2];    // phase boundaries, model / RTL
  std::size_t matched_ = 0;
  std::vector<std::uint32_t> rtl_codes_;  // RTL codes per frame, row, column, tap
  Expected e_;                            // the model's pins of this cycle (trace)
  std::vector<long long> expected_code_;  // per channel: the kernel's code of the last conversion (trace)
};

// Runs the readout RTL VTop (verilated with the parameters of tof_lockin_rtl_shape) against the
// tick-mode kernel on `setup`; `target` names the report.
template <class VTop>
CosimReport run_tof_lockin_harness(const CosimOptions& o, TofLockinSetup setup, const TofLockinRtlShape& shape,
                                   const std::string& target) {
  CosimReport r;
  r.target = target;
  VerilatedContext* ctx = cosim_verilator_context(o);
  const sc_core::sc_time period(1.0 / setup.cfg.readout.clock_Hz, sc_core::SC_SEC);
  LockinCosimTop<VTop> top("cosim", o, r, std::move(setup), shape, period);
  run_cosim_top(top, o.trace_path, period, top.cycle_bound());  // bounded by the schedule
  top.finish();
  finish_cosim_report(r, ctx);
  return r;
}

// `rangesim cosim <tof-lockin preset>` (tb/common/cosim_child.h): the readout with the preset's
// timing, ADC and noise on a reduced array (random_tof_lockin_setup), VTop verilated at run time.
template <class VTop>
CosimReport run_tof_lockin_preset(const ParamSet& preset, const CosimOptions& o) {
  const TofLockinConfig cfg = tof_lockin_from_params(preset);
  const TofLockinRtlShape shape = tof_lockin_rtl_shape(cfg, preset.origin());  // the limits the RTL adds
  std::mt19937_64 rng(o.seed);
  return run_tof_lockin_harness<VTop>(o, random_tof_lockin_setup(cfg, shape.adc_channels / 2, o.cycles, o.seed, rng),
                                      shape, preset_target_name(preset));
}

// `rangesim cosim tof-lockin --rtl FILE.sv` (the built-in target with a user's RTL, run on its
// instance preset): timings drawn from their ranges as the built-in target draws them
// (random_tof_lockin_setup without a preset), within the preset's counter widths.
template <class VTop>
CosimReport run_tof_lockin_builtin(const ParamSet& preset, const CosimOptions& o) {
  const TofLockinRtlShape shape = tof_lockin_rtl_shape(tof_lockin_from_params(preset), preset.origin());
  std::mt19937_64 rng(o.seed);
  return run_tof_lockin_harness<VTop>(o, random_tof_lockin_setup(o.cycles, o.seed, rng), shape,
                                      preset_target_name(preset));
}

}  // namespace tof_lockin_harness

using tof_lockin_harness::run_tof_lockin_builtin;
using tof_lockin_harness::run_tof_lockin_harness;
using tof_lockin_harness::run_tof_lockin_preset;

}  // namespace rangesim::tb
