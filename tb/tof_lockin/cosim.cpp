// Co-simulation of the tof-lockin readout: rtl/tof_lockin/tof_lockin_sequencer.sv (with its
// lockin_gate_generator) and one rtl/tof_lockin/column_adc.sv per simulated column and tap, against
// TofLockinSensorKernel in tick mode (one step = one clock cycle; the co-simulation runs gate
// and readout phases on one clock, the schedule counts cycles).
//
// Per cycle: phase, gate pins, light, row, frame and busy of the sequencer against the kernel's
// state before its step. Transactions: phase boundaries (phase, cycle), the ADC code of every
// (frame, row, column, tap) when the row's conversion ends, and the kernel's ADC inputs against
// a look-ahead run. Golden checks: eq. 2.25 applied to the RTL codes (golden::max_range_m) gives
// the kernel's range of every pixel and range map, NaN where the kernel rejects the pixel.
//
// The analog side: the ADC inputs of a row are known only at the end of the kernel's
// conversion, so a look-ahead kernel with the same configuration and seed runs the whole
// sequence first (deterministic noise streams) and drives the comparators.
#include <verilated.h>
#include <verilated_vcd_sc.h>

#include <cmath>
#include <memory>
#include <random>
#include <systemc>
#include <vector>

#include "Vcolumn_adc.h"
#include "Vtof_lockin_sequencer.h"
#include "core/tof_lockin/config.h"
#include "golden/tof_lockin/pulse_timing.h"
#include "systemc/tof_lockin/sensor_kernel.h"
#include "tb/common/cosim_run.h"
#include "tb/common/cosim_scoreboard.h"
#include "tb/tof_lockin/lockin_gate_generator_cosim.h"

namespace rangesim::tb {
namespace {

using namespace rangesim::systemc::lockin;

constexpr const char* kMsgType = "rangesim/cosim/tof-lockin";
constexpr int kResetCycles = 3;

struct Setup {
  TofLockinConfig cfg;
  LockinSimOptions sim;
  std::vector<LockinPixelStimulus> stim;
  long long frames = 2;
};

// Parameters within the preset ranges, reduced array: T0 1..10 gate cycles (10-100 ns at
// 100 MHz), duty 1/2..1/10, N_acc 1..50, 2..5 rows x 1..4 columns, 4..8-bit ADC with
// 2^bits..2^bits+3 conversion cycles, 2 x columns..+4 output cycles; signal 10 pA..1.5 nA and
// background 10 fA..10 nA log-uniform, delay within T0.
Setup random_setup(const CosimOptions& o, std::mt19937_64& rng) {
  Setup s;
  auto ui = [&](int a, int b) { return std::uniform_int_distribution<int>(a, b)(rng); };
  std::uniform_real_distribution<double> u(0.0, 1.0);
  TofLockinConfig& c = s.cfg;
  const int t0 = ui(1, 10), m = ui(2, 10);
  c.source.pulse_width_s = t0 / c.gates.clock_Hz;
  c.source.duty_cycle = 1.0 / m;
  c.gates.accumulations_per_frame = ui(1, 50);
  c.pixel.rows = ui(2, 5);
  c.pixel.columns = ui(1, 4);
  c.readout.adc_bits = ui(4, 8);
  c.readout.adc_conversion_cycles = (1LL << c.readout.adc_bits) + ui(0, 3);
  c.readout.output_cycles_per_row = 2 * c.pixel.columns + ui(0, 4);
  c.readout.ambient_subtraction = u(rng) < 0.8;
  s.sim.noise = true;
  s.sim.event_skipping = false;  // tick mode: one step per clock cycle
  s.sim.seed = o.seed;
  for (int p = 0; p < c.pixel.rows * c.pixel.columns; ++p) {
    LockinPixelStimulus x;
    x.signal_A = 1e-11 * std::pow(150.0, u(rng));
    x.background_A = 1e-14 * std::pow(1e6, u(rng));
    x.delay_s = c.source.pulse_width_s * u(rng);
    s.stim.push_back(x);
  }
  const long long frame_cycles = c.gates.accumulations_per_frame * t0 * m +
                                 c.pixel.rows * (c.readout.adc_conversion_cycles + c.readout.output_cycles_per_row);
  s.frames = std::max<long long>(2, (static_cast<long long>(o.cycles) + frame_cycles - 1) / frame_cycles);
  if (c.readout.ambient_subtraction && s.frames % 2) ++s.frames;
  s.frames = std::min<long long>(s.frames, 65534);
  return s;
}

struct Event {
  long long frame, row;
  int phase;
  std::uint64_t cycle;
  bool operator==(const Event& b) const {
    return phase == b.phase && cycle == b.cycle;  // frame and row are context
  }
};
std::ostream& operator<<(std::ostream& os, const Event& e) {
  return os << phase_name(static_cast<LockinPhase>(e.phase)) << " from cycle " << e.cycle;
}

class LockinCosimTop : public sc_core::sc_module {
 public:
  sc_core::sc_clock clk;
  sc_core::sc_signal<bool> rst{"rst", true}, start{"start"}, ambient{"ambient"};
  sc_core::sc_signal<std::uint32_t> t0{"t0"}, period{"period"}, acc_n{"acc_n"}, rows{"rows"}, conv{"conv"},
      outc{"outc"}, frames{"frames"}, bits{"bits"};
  sc_core::sc_signal<bool> busy{"busy"}, tx1{"tx1"}, tx2{"tx2"}, txd{"txd"}, light{"light"}, adc_start{"adc_start"},
      frame_done{"frame_done"};
  sc_core::sc_signal<std::uint32_t> phase{"phase"}, row{"row"}, frame{"frame"};
  Vtof_lockin_sequencer rtl{"rtl"};
  // One column ADC per (column, tap): index 2 c + k.
  std::vector<std::unique_ptr<Vcolumn_adc>> adcs;
  std::vector<std::unique_ptr<sc_core::sc_signal<bool>>> cmp, adc_busy, adc_done;
  std::vector<std::unique_ptr<sc_core::sc_signal<std::uint32_t>>> ramp, code;

  SC_HAS_PROCESS(LockinCosimTop);
  LockinCosimTop(sc_core::sc_module_name name, const CosimOptions& o, CosimReport& report, Setup setup,
                 sc_core::sc_time period_time)
      : sc_core::sc_module(name),
        clk("clk", period_time),
        o_(o),
        r_(report),
        sb_(report, kMsgType),
        s_(std::move(setup)),
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
    const int n = 2 * s_.cfg.pixel.columns;
    for (int i = 0; i < n; ++i) {
      const std::string id = "adc" + std::to_string(i);
      adcs.push_back(std::make_unique<Vcolumn_adc>(id.c_str()));
      cmp.push_back(std::make_unique<sc_core::sc_signal<bool>>((id + "_cmp").c_str()));
      adc_busy.push_back(std::make_unique<sc_core::sc_signal<bool>>((id + "_busy").c_str()));
      adc_done.push_back(std::make_unique<sc_core::sc_signal<bool>>((id + "_done").c_str()));
      ramp.push_back(std::make_unique<sc_core::sc_signal<std::uint32_t>>((id + "_ramp").c_str()));
      code.push_back(std::make_unique<sc_core::sc_signal<std::uint32_t>>((id + "_code").c_str()));
      Vcolumn_adc& a = *adcs.back();
      a.clk(clk);
      a.rst(rst);
      a.start_i(adc_start);
      a.conversion_cycles_i(conv);
      a.bits_i(bits);
      a.cmp_i(*cmp.back());
      a.busy_o(*adc_busy.back());
      a.ramp_o(*ramp.back());
      a.done_o(*adc_done.back());
      a.code_o(*code.back());
    }
    rtl_codes_.assign(static_cast<std::size_t>(s_.frames) * s_.cfg.pixel.rows * n, 0);
    SC_THREAD(stimulus);
    sensitive << clk.posedge_event();
    SC_METHOD(monitor);
    sensitive << clk.negedge_event();
    dont_initialize();
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
    return rtl_codes_[(static_cast<std::size_t>(f) * s_.cfg.pixel.rows + rr) * 2 * s_.cfg.pixel.columns + 2 * cc + k];
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
    sb_.pin("light_o", f, cycle, e_tx1 && run && kernel_.led_on(), light.read());
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
    // Comparators for this cycle (the analog side: the look-ahead's inputs of this row).
    const double lsb = adc_.lsb_V();
    for (std::size_t i = 0; i < adcs.size(); ++i) {
      const double v =
          run && ph == LockinPhase::AdcConversion
              ? ahead_.adc_input_V(f, static_cast<int>(rrow), static_cast<int>(i / 2), static_cast<int>(i % 2))
              : 0.0;
      // V < (ramp + 1) LSB, in the kernel's own arithmetic (floor(V / LSB)) so that inputs on a
      // code boundary compare as the kernel rounds them.
      cmp[i]->write(std::floor(v / lsb) <= static_cast<double>(ramp[i]->read()));
    }
    // Advance the model as the RTL does at the coming edge.
    if (run) kernel_.step();
    if (!started_ && start.read() && !rst.read()) started_ = true;
  }

  void check_codes(std::uint64_t cycle) {
    const long long f = kernel_.frame();
    const int rr = kernel_.readout_row();
    for (std::size_t i = 0; i < adcs.size(); ++i) {
      const int cc = static_cast<int>(i / 2), k = static_cast<int>(i % 2);
      long long got = code[i]->read();
      if (o_.inject_fault == "adc_code_off_by_one" && f == 0 && rr == 1 && i == 0) {
        got += got < adc_.top_code() ? 1 : -1;
        r_.fault_injected = true;
        r_.fault_site = "frame 0 row 1 column 0 tap 1: RTL code_o off by one";
      }
      rtl_code(f, rr, cc, k) = static_cast<std::uint32_t>(got);
      sb_.expect(k == 0 ? "adc_code tap1" : "adc_code tap2", f, rr, cc, cycle, kernel_.code(f, rr, cc, k), got);
      sb_.expect("adc_input_V (tick vs look-ahead)", f, rr, cc, cycle, kernel_.adc_input_V(f, rr, cc, k),
                 ahead_.adc_input_V(f, rr, cc, k));
    }
  }

  CosimOptions o_;
  CosimReport& r_;
  CosimScoreboard sb_;
  Setup s_;
  TofLockinSensorKernel kernel_;  // reference, stepped once per cycle
  TofLockinSensorKernel ahead_;   // same run, finished up front (drives the comparators)
  ColumnAdcKernel adc_;
  bool started_ = false;  // start_i seen: the kernel steps from the next cycle
  std::uint64_t cycle_ = 0;
  bool prev_tx2_ = false;  // RTL tx2 of the previous cycle (fault injection)
  LockinPhase prev_phase_ = LockinPhase::Idle;
  int last_phase_[2] = {0, 0};  // phase of the previous cycle, model / RTL
  std::vector<Event> ev_[2];    // phase boundaries, model / RTL
  std::size_t matched_ = 0;
  std::vector<std::uint32_t> rtl_codes_;  // RTL codes per frame, row, column, tap
};

}  // namespace

CosimReport run_tof_lockin_cosim(const CosimOptions& o) {
  CosimReport r;
  r.target = "tof-lockin";
  VerilatedContext* ctx = cosim_verilator_context(o);
  std::mt19937_64 rng(o.seed);
  Setup s = random_setup(o, rng);
  const sc_core::sc_time period(1.0 / s.cfg.readout.clock_Hz, sc_core::SC_SEC);
  const long long bound =
      10 + s.frames * (s.cfg.gates.accumulations_per_frame * 100 +
                       s.cfg.pixel.rows * (s.cfg.readout.adc_conversion_cycles + s.cfg.readout.output_cycles_per_row));
  LockinCosimTop top("cosim", o, r, std::move(s), period);
  run_cosim_top(top, o.trace_path, period, bound); // bounded by the schedule
  top.finish();
  finish_cosim_report(r, ctx);
  return r;
}

}  // namespace rangesim::tb
