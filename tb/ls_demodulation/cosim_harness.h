#pragma once
// Co-simulation harness of rtl/ls_demodulation/ls_demodulation_sequencer.sv against
// DemodSensorKernel (tb/ls_demodulation/cosim.h), templated on the verilated class: one harness
// for the built-in instance (tb/ls_demodulation/cosim.cpp) and the instances verilated at run
// time for a preset (tb/common/rtl_build.h). The array width and readout come from the config
// (verilog_parameters(), tb/ls_demodulation/verilog_parameters.h).
//
// Timing: the falling-edge monitor compares the RTL pins with the kernel's state for this
// cycle, drives the comparator outputs of the row the kernel reads in this cycle (sampled by
// the RTL at the coming rising edge), then ticks the kernel (the same edge). The kernel's
// strobes after a tick describe the next cycle, so they are kept until the next monitor call.
#include <verilated.h>
#include <verilated_vcd_sc.h>

#include <cmath>
#include <memory>
#include <optional>
#include <random>
#include <systemc>
#include <vector>

#include "core/ls_demodulation/config.h"
#include "golden/ls_demodulation/front_end.h"
#include "systemc/ls_demodulation/sensor_kernel.h"
#include "core/params.h"
#include "tb/common/cosim_run.h"
#include "tb/common/cosim_child.h"
#include "tb/common/cosim_ports.h"
#include "tb/common/cosim_scoreboard.h"
#include "tb/ls_demodulation/stimulus.h"
#include "tb/ls_demodulation/verilog_parameters.h"

namespace rangesim::tb {
namespace ls_demodulation_harness {

// The clock-level model this harness drives (no using-directive in a header).
using rangesim::systemc::ActivationRow;
using rangesim::systemc::AddressSearchPins;
using rangesim::systemc::DemodKernelOptions;
using rangesim::systemc::DemodNoiseSwitches;
using rangesim::systemc::DemodRowResult;
using rangesim::systemc::DemodSensorKernel;
using rangesim::systemc::DemodStimulus;

constexpr const char* kMsgType = "rangesim/cosim/ls-demodulation";
constexpr int kResetCycles = 3;

using Setup = LsDemodulationSetup;

struct Expect {  // the kernel's pins for one cycle
  int phase = 3;
  int row = 0;
  bool row_valid = false;
  int valid_row = -1;  // the row whose result completed
  bool found = false;
  int left = 0, right = 0;
  long long valid_frame = -1;  // its frame
};

// VTop: the sequencer verilated with verilog_parameters(config) (act_i's C++ type follows COLUMNS).
template <class VTop>
class DemodCosimTop : public sc_core::sc_module {
 public:
  sc_core::sc_clock clk;
  VTop rtl{"rtl"};
  sc_core::sc_signal<bool> rst{"rst", true}, start{"start"};
  sc_core::sc_signal<std::uint32_t> window{"window"}, detections{"detections"}, rows{"rows"};
  sc_core::sc_signal<std::uint32_t> frames{"frames"};
  sc_core::sc_signal<PortData<decltype(rtl.act_i)>> act{"act"};
  sc_core::sc_signal<bool> busy{"busy"}, integ_reset{"integ_reset"}, latch{"latch"}, search_start{"search_start"},
      addr_valid{"addr_valid"}, addr_bit{"addr_bit"}, row_valid{"row_valid"}, found{"found"};
  sc_core::sc_signal<std::uint32_t> phase{"phase"}, row{"row"}, decision{"decision"}, frame{"frame"}, left{"left"},
      right{"right"};

  SC_HAS_PROCESS(DemodCosimTop);
  DemodCosimTop(sc_core::sc_module_name name, const CosimOptions& o, CosimReport& report, Setup setup,
                sc_core::sc_time period_time)
      : sc_core::sc_module(name),
        clk("clk", period_time),
        o_(o),
        r_(report),
        sb_(report, kMsgType),
        s_(std::move(setup)),
        kernel_(s_.cfg, options(o)) {
    rtl.clk(clk);
    rtl.rst(rst);
    rtl.start_i(start);
    rtl.window_cycles_i(window);
    rtl.detections_i(detections);
    rtl.rows_i(rows);
    rtl.frames_i(frames);
    rtl.act_i(act);
    rtl.busy_o(busy);
    rtl.phase_o(phase);
    rtl.integ_reset_o(integ_reset);
    rtl.latch_o(latch);
    rtl.row_o(row);
    rtl.decision_o(decision);
    rtl.frame_o(frame);
    rtl.search_start_o(search_start);
    rtl.addr_valid_o(addr_valid);
    rtl.addr_bit_o(addr_bit);
    rtl.row_valid_o(row_valid);
    rtl.found_o(found);
    rtl.left_o(left);
    rtl.right_o(right);
    const int R = s_.cfg.pixel.rows;
    prev_det_.assign(static_cast<size_t>(R), 0);
    SC_THREAD(stimulus);
    sensitive << clk.posedge_event();
    SC_METHOD(monitor);
    sensitive << clk.negedge_event();
    dont_initialize();
  }

  // The clock-level model's pins of every cycle, beside the RTL's in the trace
  // (tb/common/cosim_run.h), as the scoreboard compares them at the falling edge.
  void trace_expected(systemc::Waveform& w) {
    systemc::Waveform::ValueNames phases;
    for (int p = 0; p <= static_cast<int>(systemc::DemodPhase::Done); ++p)
      phases.push_back({p, systemc::to_string(static_cast<systemc::DemodPhase>(p))});
    w.add(e_.phase, "sequencer", "phase", phases);
    w.add(e_.row, "sequencer", "row");
    w.add(e_.row_valid, "readout", "row_valid");
    w.add(e_.found, "readout", "found");
    w.add(e_.left, "readout", "left");
    w.add(e_.right, "readout", "right");
  }

  long long cycle_bound() const { return kResetCycles + 10 + s_.frames * kernel_.frame_cycles(); }
  // Per frame and row, the centre rebuilt from the RTL's row results against the kernel's.
  void finish() {
    if (!finished_) sb_.mismatch("frames", -1, -1, -1, cycle_, std::to_string(s_.frames), std::to_string(frame_));
    for (std::size_t f = 0; f < kernel_rows_.size() && f < rtl_rows_.size(); ++f) {
      for (std::size_t rr = 0; rr < kernel_rows_[f].size(); ++rr) {
        const DemodRowResult& k = kernel_rows_[f][rr];
        const RtlRow& a = rtl_rows_[f][rr];
        const long long ff = static_cast<long long>(f), r2 = static_cast<long long>(rr);
        sb_.expect("detections", ff, r2, -1, cycle_, k.detections, a.detections);
        const double centre = a.detections ? a.centre_sum_px / a.detections : 0.0;
        sb_.expect("centre_px", ff, r2, -1, cycle_, k.centre_px(), centre);
        if (noise_free(o_)) {
          if (f == 0) golden_.push_back(golden_centre_px(static_cast<int>(rr)));
          if (golden_[rr]) {
            ++r_.golden_checks;
            if (!(a.detections > 0 && centre == *golden_[rr]))
              sb_.mismatch("golden_centre_px", ff, r2, -1, cycle_, std::to_string(*golden_[rr]),
                           a.detections ? std::to_string(centre) : std::string("no detection"));
          }
        }
      }
    }
  }

 private:
  // Odd seeds run noise-free, so the centres can also be checked against the golden model.
  static bool noise_free(const CosimOptions& o) { return o.seed % 2 == 1; }
  static DemodKernelOptions options(const CosimOptions& o) {
    DemodKernelOptions k;
    k.event_skipping = false;  // cycle by cycle
    k.seed = o.seed;
    if (noise_free(o)) k.noise = DemodNoiseSwitches::none();
    return k;
  }

  // Golden centre of row r, noise-free: the pixels whose correlator output D reaches the
  // threshold (thesis eq. for the demodulating pixel, golden/ls_demodulation/front_end.h), centre
  // (first + last) / 2; every decision sees the same D. Empty when nothing activates or a pixel
  // sits within rounding of the threshold (golden and kernel agree to ~1e-9 of the swing there).
  std::optional<double> golden_centre_px(int r) const {
    const LsDemodulationConfig& c = s_.cfg;
    int first = -1, last = -1;
    for (int col = 0; col < c.pixel.columns; ++col) {
      const std::size_t i = static_cast<std::size_t>(r) * c.pixel.columns + col;
      const golden::CorrelatorOutput g = golden::correlate_periodic(
          c, golden::pixel_segments(c, s_.stim.beam_A[i], s_.stim.background_A[i]), c.correlator.cycles);
      if (std::fabs(g.diff_V - c.comparator.threshold_V) <= 1e-10 + 1e-9 * std::fabs(g.plus_V)) return std::nullopt;
      if (g.diff_V >= c.comparator.threshold_V) last = col, first = first < 0 ? col : first;
    }
    if (first < 0) return std::nullopt;
    return 0.5 * (first + last);
  }

  void stimulus() {
    window.write(static_cast<std::uint32_t>(kernel_.schedule().window_cycles()));
    detections.write(static_cast<std::uint32_t>(s_.cfg.grid.detections));
    rows.write(static_cast<std::uint32_t>(s_.cfg.pixel.rows));
    frames.write(static_cast<std::uint32_t>(s_.frames));
    for (int i = 0; i < kResetCycles; ++i) wait();
    rst.write(false);
    wait();
    start.write(true);
    wait();
    start.write(false);
  }

  void monitor() {
    const std::uint64_t cycle = cycle_++;
    r_.cycles = cycle_;
    if (cycle < kResetCycles) return;
    const long long f = running_ ? frame_ : -1;
    sb_.pin("busy_o", f, cycle, running_, busy.read());
    sb_.pin("phase_o", f, cycle, static_cast<std::uint32_t>(e_.phase), phase.read());
    const bool e_integ_reset = running_ && e_.phase == 0 && first_integ_;
    sb_.pin("integ_reset_o", f, cycle, e_integ_reset, integ_reset.read());
    sb_.pin("latch_o", f, cycle, e_.phase == 1, latch.read());
    if (e_.phase == 2) {
      sb_.pin("row_o", f, cycle, static_cast<std::uint32_t>(e_.row), row.read());
      sb_.pin("decision_o", f, cycle, static_cast<std::uint32_t>(decision_), decision.read());
      sb_.pin("frame_o", f, cycle, static_cast<std::uint32_t>(frame_), frame.read());
      sb_.pin("search_start_o", f, cycle, row_cycle_ == 0, search_start.read());
    }
    // The address stream against the kernel's search pins (cycle-exact, shared kernel).
    bool a_bit = addr_bit.read();
    if (o_.inject_fault == "address_bit_flip" && addr_valid.read() && !r_.fault_injected &&
        (frame_ > 0 || e_.row >= 1)) {
      a_bit = !a_bit;
      r_.fault_injected = true;
      r_.fault_site = "frame " + std::to_string(frame_) + " row " + std::to_string(e_.row) +
                      ": first streamed RTL address bit from frame 0 row 1 on flipped";
    }
    if (e_.phase == 2 && row_cycle_ > 0) {
      const AddressSearchPins p = kernel_.search_pins();
      sb_.pin("addr_valid_o", f, cycle, p.addr_valid, addr_valid.read());
      if (p.addr_valid) sb_.pin("addr_bit_o", f, cycle, p.addr_bit, a_bit);
    }
    // Row results (found, left, right) as transactions.
    bool a_valid = row_valid.read();
    if (o_.inject_fault == "dropped_row" && a_valid && frame_ == 0 && e_.valid_row == 1 && !r_.fault_injected) {
      a_valid = false;
      r_.fault_injected = true;
      r_.fault_site = "frame 0 row 1: the RTL row result is dropped";
    }
    if (e_.row_valid || a_valid) {
      const int vr = e_.valid_row;
      sb_.expect("row_valid", e_.valid_frame, vr, -1, cycle, e_.row_valid, a_valid);
      if (e_.row_valid && a_valid) {
        sb_.expect("found", e_.valid_frame, vr, -1, cycle, e_.found, found.read());
        if (e_.found) {
          sb_.expect("left address", e_.valid_frame, vr, -1, cycle, e_.left, static_cast<int>(left.read()));
          sb_.expect("right address", e_.valid_frame, vr, -1, cycle, e_.right, static_cast<int>(right.read()));
        }
      }
      if (a_valid && found.read() && vr >= 0 && e_.valid_frame >= 0) {
        RtlRow& x = rtl_rows_[static_cast<size_t>(e_.valid_frame)][static_cast<size_t>(vr)];
        x.centre_sum_px += 0.5 * (left.read() + right.read());
        ++x.detections;
      }
    }
    // Comparator outputs of the row the kernel reads in this cycle.
    if (e_.phase == 2) {
      const ActivationRow& a = kernel_.result().activations[static_cast<size_t>(e_.row)];
      const int columns = s_.cfg.pixel.columns;
      std::vector<std::uint32_t> words(static_cast<std::size_t>((columns + 31) / 32), 0U);
      for (int c = 0; c < columns; ++c)
        if (a.test(c)) words[static_cast<std::size_t>(c / 32)] |= 1U << (c % 32);
      PortData<decltype(rtl.act_i)> v{};
      port_from_words(words, v);
      act.write(v);
    }
    // The edge: start the first frame, or tick.
    if (!running_) {
      e_ = Expect{};  // idle from the next cycle on (the last row result was this cycle's)
      if (start.read() && !rst.read() && !started_) {
        started_ = true;
        begin(0);
      }
      return;
    }
    const int row_before = kernel_.row();
    const int phase_before = static_cast<int>(kernel_.phase());
    kernel_.tick();
    Expect n;
    n.phase = static_cast<int>(kernel_.phase());
    n.row = kernel_.row();
    n.row_valid = kernel_.row_valid();
    if (n.row_valid) {
      const DemodRowResult& lr = kernel_.last_row();
      n.valid_row = row_before;
      n.valid_frame = frame_;
      n.found = lr.detections > prev_det_[static_cast<size_t>(row_before)];
      prev_det_[static_cast<size_t>(row_before)] = lr.detections;
      n.left = lr.left, n.right = lr.right;
    }
    first_integ_ = phase_before != 0 && n.phase == 0;
    if (phase_before == 2 && n.phase == 0) ++decision_;
    row_cycle_ = (n.phase == 2 && (phase_before != 2 || n.row != row_before)) ? 0 : row_cycle_ + 1;
    if (kernel_.frame_done()) {
      end_frame(cycle);
      if (++frame_ < s_.frames) {
        begin(frame_);
        n.phase = 0;
        first_integ_ = true;
      } else {
        running_ = false;
        finished_ = true;
      }
    }
    e_ = n;
  }

  void begin(long long f) {
    kernel_.start_frame(static_cast<std::uint64_t>(f), s_.stim);
    running_ = true;
    first_integ_ = true;
    decision_ = 0;
    row_cycle_ = 0;
    e_ = Expect{};
    e_.phase = 0;
    std::fill(prev_det_.begin(), prev_det_.end(), 0);
    rtl_rows_.emplace_back(static_cast<size_t>(s_.cfg.pixel.rows));
  }

  void end_frame(std::uint64_t) { kernel_rows_.push_back(kernel_.result().rows); }

  struct RtlRow {
    int detections = 0;        // detecting decisions
    double centre_sum_px = 0;  // sum of (left + right) / 2
  };

  CosimOptions o_;
  CosimReport& r_;
  CosimScoreboard sb_;
  Setup s_;
  DemodSensorKernel kernel_;
  Expect e_;  // the kernel's pins for the current cycle
  bool started_ = false, running_ = false, finished_ = false, first_integ_ = false;
  long long frame_ = 0;
  int decision_ = 0, row_cycle_ = 0;
  std::vector<int> prev_det_;                             // kernel detections per row so far (this frame)
  std::vector<std::vector<RtlRow>> rtl_rows_;             // [frame][row] from the RTL
  std::vector<std::vector<DemodRowResult>> kernel_rows_;  // [frame][row] kernel results
  std::vector<std::optional<double>> golden_;             // [row] golden centre (noise-free runs)
  std::uint64_t cycle_ = 0;
};

// Runs the sequencer RTL VTop, verilated with verilog_parameters(base), against the kernel on a
// random setup drawn on `base`; `target` names the report.
template <class VTop>
CosimReport run_ls_demodulation_harness(const CosimOptions& o, const LsDemodulationConfig& base,
                                        const std::string& target) {
  CosimReport r;
  r.target = target;
  VerilatedContext* ctx = cosim_verilator_context(o);
  std::mt19937_64 rng(o.seed);
  Setup s = random_ls_demodulation_setup(base, o.cycles, rng);
  const sc_core::sc_time period(1.0 / s.cfg.readout.clock_Hz, sc_core::SC_SEC);
  DemodCosimTop<VTop> top("cosim", o, r, std::move(s), period);
  run_cosim_top(top, o.trace_path, period, top.cycle_bound());
  top.finish();
  finish_cosim_report(r, ctx);
  return r;
}

// `rangesim cosim <ls-demodulation preset>` (tb/common/cosim_child.h): the sequencer at the
// preset's array width and readout, VTop verilated at run time with verilog_parameters().
template <class VTop>
CosimReport run_ls_demodulation_preset(const ParamSet& preset, const CosimOptions& o) {
  const LsDemodulationConfig cfg = ls_demodulation_from_params(preset);
  verilog_parameters(cfg, preset.origin());  // the limits the RTL adds
  return run_ls_demodulation_harness<VTop>(o, cfg, preset_target_name(preset));
}

}  // namespace ls_demodulation_harness

using ls_demodulation_harness::run_ls_demodulation_harness;
using ls_demodulation_harness::run_ls_demodulation_preset;

}  // namespace rangesim::tb
