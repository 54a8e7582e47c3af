#pragma once
// Co-simulation harness of rtl/tof_spad/tof_spad_sequencer.sv against the tof-spad kernels
// (tb/tof_spad/cosim.h), templated on the verilated class: one harness for the built-in instance
// (tb/tof_spad/cosim.cpp) and the instances verilated at run time for a preset
// (tb/common/rtl_build.h). The group's width and the RTL's field widths come from
// tof_spad_rtl_shape(config) (tb/tof_spad/verilog_parameters.h).
//
// Stimulus: for each row the avalanches of the group's CPT pixels come from SpadPixelKernel with
// the keys TofSpadKernel::simulate_group uses (same seed, frame 0, row, column), in time order.
// Each is presented in the clock cycle that contains it (cycle = laser cycle x Np + coarse),
// with the interpolator values: fine = its position in the cycle (16 bits, orders hits of one
// cycle) and corr = kernel bin (phase_bin, on the INL/DNL edges) - coarse. The expectation of
// every cycle comes from TdcGroupKernel fed the same hits; its histogram must equal
// TofSpadKernel::simulate_group's (the event-driven kernel), so the RTL is compared with both.
// Monitor on the falling edge; stimulus right after the rising edge, from the schedule only.
#include <verilated.h>
#include <verilated_vcd_sc.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cmath>
#include <fstream>
#include <map>
#include <memory>
#include <optional>
#include <random>
#include <systemc>
#include <vector>

#include "core/tof_spad/config.h"
#include "golden/tof_spad/pile_up.h"
#include "golden/tof_spad/point_model.h"
#include "systemc/tof_spad/pixel_kernel.h"
#include "systemc/tof_spad/tdc_kernel.h"
#include "systemc/tof_spad/sensor_kernel.h"
#include "core/params.h"
#include "tb/common/cosim_run.h"
#include "tb/common/cosim_child.h"
#include "tb/common/cosim_ports.h"
#include "tb/common/cosim_scoreboard.h"
#include "tb/tof_spad/stimulus.h"
#include "tb/tof_spad/verilog_parameters.h"

namespace rangesim::tb {
namespace tof_spad_harness {

// The clock-level model this harness drives (no using-directive in a header).
using rangesim::systemc::spad::GroupHistogram;
using rangesim::systemc::spad::PixelRates;
using rangesim::systemc::spad::SpadNoise;
using rangesim::systemc::spad::SpadPixelKernel;
using rangesim::systemc::spad::SpadTime;
using rangesim::systemc::spad::TdcGroupKernel;
using rangesim::systemc::spad::TdcHit;
using rangesim::systemc::spad::TofSpadKernelOptions;
using rangesim::systemc::spad::TofSpadKernel;

constexpr const char* kMsgType = "rangesim/cosim/tof-spad";
constexpr int kResetCycles = 3;
constexpr int kMaxCpt = 16;  // tof_spad_rtl_shape allows up to 16 columns per group

using Setup = TofSpadSetup;

// The model's pins of the current cycle as the scoreboard compares them (traced under
// "expected" by trace_expected()); the pulses are false in cycles without one.
struct SpadExpected {
  int phase = 0, row = 0;
  bool tdc_event = false, tdc_overflow = false;
  int tdc_lost = 0;
  long long tdc_grant = 0, tdc_code = 0;
  bool word_valid = false;
  long long word = 0;
  bool peak_valid = false;
  long long peak_code = 0, peak_count = 0, centroid_num = 0, centroid_den = 0;
};

struct CycleHits {
  std::uint32_t hit = 0;                 // bit per column
  std::uint32_t fine[kMaxCpt / 2] = {};  // FINE_BITS (16) per column, as the 32-bit words of fine_i
  std::uint64_t corr = 0;                // CORR_BITS (3) per column (two's complement)
  int recorded_column = -1;              // expectation: the column recorded (-1: none)
  TdcHit::Kind kind = TdcHit::Kind::Lost;
  int code = 0;
  int lost = 0;
};

struct RowPlan {
  std::map<long long, CycleHits> cycles;  // bin since the row's first START -> hits
  GroupHistogram expected;                // TdcGroupKernel's histogram
  GroupHistogram kernel;                  // TofSpadKernel::simulate_group's
  long long dropped = 0;                  // avalanches before the first START (never presented)
};

// VTop: rtl/tof_spad/tof_spad_sequencer.sv verilated with verilog_parameters(cfg) (the ports
// whose width follows CPT take their C++ type from it).
template <class VTop>
class SpadCosimTop : public sc_core::sc_module {
  template <class P>
  using Sig = sc_core::sc_signal<PortData<P>>;

 public:
  sc_core::sc_clock clk;
  VTop rtl{"rtl"};
  sc_core::sc_signal<bool> rst{"rst", true}, start{"start"};
  sc_core::sc_signal<std::uint32_t> rows{"rows"}, laser{"laser"}, np{"np"}, nc{"nc"}, be{"be"}, bo{"bo"}, w{"w"};
  Sig<decltype(rtl.hit_i)> hit{"hit"};
  Sig<decltype(rtl.corr_i)> corr{"corr"};
  Sig<decltype(rtl.fine_i)> fine{"fine"};
  sc_core::sc_signal<bool> ready{"ready"}, ev{"ev"}, ovf{"ovf"}, word_valid{"word_valid"}, peak_valid{"peak_valid"},
      saturated{"saturated"};
  sc_core::sc_signal<std::uint32_t> phase{"phase"}, row{"row"}, code{"code"}, lost{"lost"}, word_code{"word_code"},
      word{"word"}, peak_code{"peak_code"}, peak_count{"peak_count"}, den{"den"};
  Sig<decltype(rtl.tdc_grant_o)> grant{"grant"};
  Sig<decltype(rtl.word_column_o)> word_column{"word_column"};
  Sig<decltype(rtl.peak_column_o)> peak_column{"peak_column"};
  sc_core::sc_signal<std::uint64_t> num{"num"};

  SC_HAS_PROCESS(SpadCosimTop);
  SpadCosimTop(sc_core::sc_module_name name, const CosimOptions& o, CosimReport& report, Setup setup,
               const TofSpadRtlShape& shape, const std::string& record_path, sc_core::sc_time period_time)
      : sc_core::sc_module(name),
        clk("clk", period_time),
        o_(o),
        r_(report),
        sb_(report, kMsgType),
        s_(std::move(setup)),
        shape_(shape),
        cpt_(shape.cpt),
        count_max_((1LL << shape.count_bits) - 1),
        kernel_(s_.cfg, s_.rows, cpt_, opts(o)) {
    const golden::spad::SpadModel model(s_.cfg);
    const golden::spad::PileUpInput in =
        model.pile_up_input(std::vector<double>(static_cast<size_t>(kernel_.phase_bins()), 0.0));
    block_event_ = in.block_event_bins;
    block_overflow_ = in.block_overflow_bins;
    for (int rr = 0; rr < s_.rows; ++rr) plans_.push_back(plan_row(rr));
    row_len_ =
        kernel_.laser_cycles() * kernel_.phase_bins() + kernel_.readout_words_per_row() * kernel_.cycles_per_word();
    rtl.clk(clk);
    rtl.rst(rst);
    rtl.start_i(start);
    rtl.rows_i(rows);
    rtl.laser_cycles_i(laser);
    rtl.phase_bins_i(np);
    rtl.codes_i(nc);
    rtl.block_event_i(be);
    rtl.block_overflow_i(bo);
    rtl.cycles_per_word_i(w);
    rtl.hit_i(hit);
    rtl.fine_i(fine);
    rtl.corr_i(corr);
    rtl.ready_o(ready);
    rtl.phase_o(phase);
    rtl.row_o(row);
    rtl.tdc_event_o(ev);
    rtl.tdc_overflow_o(ovf);
    rtl.tdc_code_o(code);
    rtl.tdc_grant_o(grant);
    rtl.tdc_lost_o(lost);
    rtl.word_valid_o(word_valid);
    rtl.word_column_o(word_column);
    rtl.word_code_o(word_code);
    rtl.word_o(word);
    rtl.peak_valid_o(peak_valid);
    rtl.peak_column_o(peak_column);
    rtl.peak_code_o(peak_code);
    rtl.peak_count_o(peak_count);
    rtl.centroid_num_o(num);
    rtl.centroid_den_o(den);
    rtl.saturated_o(saturated);
    rtl_events_.assign(static_cast<size_t>(s_.rows) * cpt_,
                       std::vector<long long>(static_cast<size_t>(kernel_.codes()), 0));
    if (!record_path.empty()) record_.open(record_path);
    SC_THREAD(stimulus);
    sensitive << clk.posedge_event();
    SC_METHOD(monitor);
    sensitive << clk.negedge_event();
    dont_initialize();
  }

  long long cycle_bound() const { return kResetCycles + clear_cycles() + 20 + s_.rows * row_len_; }

  // The kernels' pins of every cycle beside the RTL's in the trace (tb/common/cosim_run.h).
  void trace_expected(systemc::Waveform& w) {
    const systemc::Waveform::ValueNames phases{{0, "idle"}, {1, "laser_cycles"}, {2, "histogram_readout"}};
    w.add(e_.phase, "sequencer", "phase", phases);
    w.add(e_.row, "sequencer", "row");
    w.add(e_.tdc_event, "tdc", "event");
    w.add(e_.tdc_overflow, "tdc", "overflow");
    w.add(e_.tdc_lost, "tdc", "lost");
    w.add(e_.tdc_grant, "tdc", "grant");
    w.add(e_.tdc_code, "tdc", "code");
    w.add(e_.word_valid, "histogram", "word_valid");
    w.add(e_.word, "histogram", "word");
    w.add(e_.peak_valid, "histogram", "peak_valid");
    w.add(e_.peak_code, "histogram", "peak_code");
    w.add(e_.peak_count, "histogram", "peak_count");
    w.add(e_.centroid_num, "histogram", "centroid_num");
    w.add(e_.centroid_den, "histogram", "centroid_den");
  }

  // Histograms of the two kernels, the estimator on the RTL histograms, the phase totals.
  void finish() {
    const long long f = -1;
    if (std::getenv("RANGESIM_COSIM_VERBOSE")) {  // what the stimulus exercised
      long long events = 0, ovf = 0, lost = 0, multi = 0;
      for (const RowPlan& p : plans_) {
        for (const auto& e : p.expected.events)
          for (long long x : e) events += x;
        ovf += p.expected.overflows, lost += p.expected.lost_busy;
        for (const auto& kv : p.cycles) multi += __builtin_popcount(kv.second.hit) > 1;
      }
      std::fprintf(stderr,
                   "tof-spad cosim: %d rows, Np %d, Nc %d, L %lld, W %lld, block %d/%d: "
                   "%lld events, %lld overflows, %lld lost, %lld cycles with several hits\n",
                   s_.rows, kernel_.phase_bins(), kernel_.codes(), kernel_.laser_cycles(), kernel_.cycles_per_word(),
                   block_event_, block_overflow_, events, ovf, lost, multi);
    }
    for (int rr = 0; rr < s_.rows; ++rr) {
      const RowPlan& p = plans_[static_cast<size_t>(rr)];
      sb_.expect("kernel overflows (TdcGroupKernel vs simulate_group)", f, rr, -1, cycle_, p.kernel.overflows,
                 p.expected.overflows);
      sb_.expect("kernel lost (TdcGroupKernel + before START vs simulate_group)", f, rr, -1, cycle_, p.kernel.lost_busy,
                 p.expected.lost_busy + p.dropped);
      for (int cc = 0; cc < cpt_; ++cc) {
        const auto& ke = p.kernel.events[static_cast<size_t>(cc)];
        sb_.expect("kernel histogram (TdcGroupKernel vs simulate_group)", f, rr, cc, cycle_, vec_text(ke),
                   vec_text(p.expected.events[static_cast<size_t>(cc)]));
        const auto& got = rtl_events_[static_cast<size_t>(rr) * cpt_ + cc];
        const std::optional<double> want_t = kernel_.estimate(ke, p.kernel.armed);
        const std::optional<double> got_t = kernel_.estimate(got, p.kernel.armed);
        ++r_.golden_checks;
        const auto txt = [](const std::optional<double>& t) {
          return t ? std::to_string(*t * 1e9) + " ns" : std::string("no detection");
        };
        if (txt(want_t) != txt(got_t) || (want_t && got_t && *want_t != *got_t))
          sb_.mismatch("estimated round trip (golden estimator on RTL histogram)", f, rr, cc, cycle_, txt(want_t),
                       txt(got_t));
      }
    }
    sb_.expect("laser_cycles phase cycles", f, -1, -1, cycle_, s_.rows * kernel_.laser_cycles() * kernel_.phase_bins(),
               phase_cycles_[1]);
    sb_.expect("histogram_readout phase cycles", f, -1, -1, cycle_,
               s_.rows * kernel_.readout_words_per_row() * kernel_.cycles_per_word(), phase_cycles_[2]);
  }

 private:
  // tdc_histogram clears its CPT x CODES_MAX words after reset (one a cycle), plus slack.
  long long clear_cycles() const { return static_cast<long long>(cpt_) * shape_.codes_max + 4; }
  static TofSpadKernelOptions opts(const CosimOptions& o) {
    TofSpadKernelOptions k;
    k.seed = o.seed;
    return k;
  }
  static std::string vec_text(const std::vector<long long>& v) {
    std::string s;
    for (long long x : v) s += std::to_string(x) + ",";
    return s;
  }

  // The avalanches of one row in time order, as simulate_group draws them, and what the TDC
  // makes of each (TdcGroupKernel); plus simulate_group itself for the cross-check.
  RowPlan plan_row(int rr) {
    RowPlan p;
    const double lsb = s_.cfg.tdc.lsb_s;
    const int npb = kernel_.phase_bins();
    const long long L = kernel_.laser_cycles();
    auto rates = [&](int r2, int c2) { return s_.rates[static_cast<size_t>(r2) * cpt_ + c2]; };
    std::vector<SpadPixelKernel> px;
    for (int k = 0; k < cpt_; ++k)
      px.emplace_back(s_.cfg, rates(rr, k), SpadNoise{}, L, o_.seed, 0, static_cast<std::uint32_t>(rr),
                      static_cast<std::uint32_t>(k));
    TdcGroupKernel tdc(npb, kernel_.codes(), block_event_, block_overflow_, L, cpt_);
    const int corr_min = -(1 << (shape_.corr_bits - 1)), corr_max = (1 << (shape_.corr_bits - 1)) - 1;
    const double fine_steps = static_cast<double>(1LL << shape_.fine_bits);
    for (;;) {
      int who = -1;
      SpadTime t = SpadTime::never_time();
      for (int k = 0; k < cpt_; ++k)
        if (px[static_cast<size_t>(k)].peek() < t) t = px[static_cast<size_t>(k)].peek(), who = k;
      if (who < 0) break;
      px[static_cast<size_t>(who)].pop();
      if (t.cycle < 0) {
        ++p.dropped;
        continue;
      }
      const long long lc = t.cycle;  // laser cycle and phase within it (relative times)
      if (lc >= L) break;
      const double ph = t.offset_s;
      const int bin = kernel_.phase_bin(ph);
      const int coarse = std::min(static_cast<int>(ph / lsb), npb - 1);
      const int cr = bin - coarse;
      if (cr < corr_min || cr > corr_max) throw std::runtime_error("tof-spad cosim: bin correction out of range");
      const double in_cycle = (ph - coarse * lsb) / lsb;
      const auto fq = static_cast<std::uint32_t>(std::clamp(std::floor(in_cycle * fine_steps), 0.0, fine_steps - 1));
      CycleHits& ch = p.cycles[lc * npb + coarse];
      if (ch.hit & (1U << who)) throw std::runtime_error("tof-spad cosim: two avalanches of one pixel in a cycle");
      ch.hit |= 1U << who;
      const int fb = shape_.fine_bits * who;  // FINE_BITS = 16: a field never straddles two words
      ch.fine[fb / 32] |= fq << (fb % 32);
      ch.corr |= (static_cast<std::uint64_t>(cr) & low_mask(shape_.corr_bits)) << (shape_.corr_bits * who);
      const TdcHit h = tdc.hit(who, lc, bin);
      if (h.kind == TdcHit::Kind::Lost) {
        ++ch.lost;
      } else {
        ch.recorded_column = who, ch.kind = h.kind, ch.code = h.code;
      }
    }
    p.expected = tdc.finish();
    p.kernel = kernel_.simulate_group(0, rr, 0, rates);
    return p;
  }

  void stimulus() {
    rows.write(static_cast<std::uint32_t>(s_.rows));
    laser.write(static_cast<std::uint32_t>(kernel_.laser_cycles()));
    np.write(static_cast<std::uint32_t>(kernel_.phase_bins()));
    nc.write(static_cast<std::uint32_t>(kernel_.codes()));
    be.write(static_cast<std::uint32_t>(block_event_));
    bo.write(static_cast<std::uint32_t>(block_overflow_));
    w.write(static_cast<std::uint32_t>(kernel_.cycles_per_word()));
    for (int i = 0; i < kResetCycles; ++i) wait();
    rst.write(false);
    for (long long i = 0; i < clear_cycles(); ++i) wait();  // the histogram clears its memory
    start.write(true);
    wait();
    start.write(false);
    for (int rr = 0; rr < s_.rows; ++rr) {
      const RowPlan& p = plans_[static_cast<size_t>(rr)];
      for (long long k = 0; k < row_len_; ++k) {
        const auto it = p.cycles.find(k);
        if (it != p.cycles.end()) {
          drive_hits(it->second);
        } else if (port_field(hit.read(), 0, cpt_) != 0) {
          drive_hits(CycleHits{});
        }
        wait();
      }
    }
    for (int i = 0; i < 3; ++i) wait();
    sc_core::sc_stop();
  }

  void drive_hits(const CycleHits& h) {
    PortData<decltype(rtl.hit_i)> hv{};
    PortData<decltype(rtl.fine_i)> fv{};
    PortData<decltype(rtl.corr_i)> cv{};
    port_from_words({h.hit}, hv);
    port_from_words(std::vector<std::uint32_t>(std::begin(h.fine), std::end(h.fine)), fv);
    port_from_words({static_cast<std::uint32_t>(h.corr), static_cast<std::uint32_t>(h.corr >> 32)}, cv);
    hit.write(hv);
    fine.write(fv);
    corr.write(cv);
  }

  void monitor() {
    const std::uint64_t cycle = cycle_++;
    r_.cycles = cycle_;
    if (record_.is_open()) {
      record_ << rst.read() << ' ' << start.read() << ' ' << rows.read() << ' ' << laser.read() << ' ' << np.read()
              << ' ' << nc.read() << ' ' << be.read() << ' ' << bo.read() << ' ' << w.read() << ' ' << hit.read() << ' '
              << std::hex << fine.read() << std::dec << ' ' << corr.read() << ' ' << phase.read() << ' ' << row.read()
              << ' ' << ev.read() << ' ' << ovf.read() << ' ' << code.read() << ' ' << grant.read() << ' '
              << lost.read() << ' ' << word_valid.read() << ' ' << word.read() << ' ' << peak_valid.read() << ' '
              << peak_code.read() << ' ' << peak_count.read() << ' ' << num.read() << ' ' << den.read() << '\n';
    }
    if (cycle < kResetCycles) return;
    e_.tdc_event = e_.tdc_overflow = e_.word_valid = e_.peak_valid = false;
    e_.tdc_lost = 0;
    e_.tdc_grant = 0;
    if (start_cycle_ < 0) {
      e_.phase = 0;
      sb_.pin("phase_o", -1, cycle, 0U, phase.read());
      if (start.read() && !rst.read()) start_cycle_ = static_cast<long long>(cycle);
      return;
    }
    const long long rel = static_cast<long long>(cycle) - start_cycle_ - 1;
    const bool running = rel < s_.rows * row_len_;
    const int rr = static_cast<int>(std::min<long long>(rel / row_len_, s_.rows));
    const long long k = rel % row_len_;
    // The last column of a row reports its peak in the cycle after the row's readout.
    if (k == 0 && rr > 0) {
      sb_.pin("peak_valid_o", -1, cycle, true, peak_valid.read());
      check_peak(rr - 1, cpt_ - 1, cycle);
    } else if (!running || k < kernel_.laser_cycles() * kernel_.phase_bins()) {
      sb_.pin("peak_valid_o", -1, cycle, false, peak_valid.read());
    }
    if (!running) {
      e_.phase = 0;
      sb_.pin("phase_o", -1, cycle, 0U, phase.read());
      return;
    }
    const long long integ = kernel_.laser_cycles() * kernel_.phase_bins();
    const std::uint32_t e_phase = k < integ ? 1 : 2;
    e_.phase = static_cast<int>(e_phase);
    e_.row = rr;
    ++phase_cycles_[std::min<std::uint32_t>(phase.read(), 2)];
    sb_.pin("phase_o", -1, cycle, e_phase, phase.read());
    sb_.pin("row_o", -1, cycle, static_cast<std::uint32_t>(rr), row.read());
    if (e_phase != last_phase_) sb_.expect("phase_boundary", -1, rr, -1, cycle, e_phase, phase.read());
    last_phase_ = e_phase;
    if (k < integ) {
      check_tdc(rr, k, cycle);
    } else {
      check_readout(rr, k - integ, cycle);
    }
  }

  void check_tdc(int rr, long long k, std::uint64_t cycle) {
    const RowPlan& p = plans_[static_cast<size_t>(rr)];
    const auto it = p.cycles.find(k);
    const CycleHits none;
    const CycleHits& e = it == p.cycles.end() ? none : it->second;
    const int col = e.recorded_column;
    const bool e_ev = col >= 0 && e.kind == TdcHit::Kind::Event;
    const bool e_ovf = col >= 0 && e.kind == TdcHit::Kind::Overflow;
    e_.tdc_event = e_ev, e_.tdc_overflow = e_ovf, e_.tdc_lost = e.lost;
    if (col >= 0) e_.tdc_grant = 1LL << col, e_.tdc_code = e.code;
    sb_.pin("tdc event_o", -1, cycle, e_ev, ev.read());
    sb_.pin("tdc overflow_o", -1, cycle, e_ovf, ovf.read());
    sb_.pin("tdc lost_o", -1, cycle, static_cast<std::uint32_t>(e.lost), lost.read());
    const auto g_grant = static_cast<std::uint32_t>(port_field(grant.read(), 0, cpt_));
    if (col >= 0 || g_grant != 0) {
      long long got = code.read();
      if (o_.inject_fault == "tdc_code_off_by_one" && e_ev && ++events_seen_ == 5) {
        ++got;
        r_.fault_injected = true;
        r_.fault_site = "row " + std::to_string(rr) + " column " + std::to_string(col) + " cycle " +
                        std::to_string(cycle) + ": RTL tdc code_o + 1";
      }
      const std::uint32_t e_grant = col >= 0 ? 1U << col : 0U;
      sb_.expect("tdc grant", -1, rr, col, cycle, e_grant, g_grant);
      sb_.expect("tdc_code", -1, rr, col, cycle, static_cast<long long>(e.code), got);
    }
  }

  void check_readout(int rr, long long q, std::uint64_t cycle) {
    const RowPlan& p = plans_[static_cast<size_t>(rr)];
    const long long W = kernel_.cycles_per_word(), Nc = kernel_.codes();
    const long long wi = q / W;
    const bool first = q % W == 0;
    e_.word_valid = first;
    sb_.pin("word_valid_o", -1, cycle, first, word_valid.read());
    // The previous column's results, in the cycle after its last word.
    const bool e_peak = q > 0 && first && wi % Nc == 0;
    if (e_peak) sb_.pin("peak_valid_o", -1, cycle, true, peak_valid.read());
    if (e_peak) check_peak(rr, static_cast<int>(wi / Nc) - 1, cycle);
    if (!e_peak) sb_.pin("peak_valid_o", -1, cycle, false, peak_valid.read());
    if (!first) return;
    const int cc = static_cast<int>(wi / Nc), cd = static_cast<int>(wi % Nc);
    const long long want = std::min(p.kernel.events[static_cast<size_t>(cc)][static_cast<size_t>(cd)], count_max_);
    e_.word = want;
    long long got = word.read();
    if (o_.inject_fault == "dropped_histogram_count" && !r_.fault_injected && got > 0) {
      --got;
      r_.fault_injected = true;
      r_.fault_site = "row " + std::to_string(rr) + " column " + std::to_string(cc) + " code " + std::to_string(cd) +
                      ": one count dropped from the RTL word";
    }
    rtl_events_[static_cast<size_t>(rr) * cpt_ + cc][static_cast<size_t>(cd)] = got;
    sb_.expect("histogram_bin", -1, rr, cc, cycle, want, got);
  }

  void check_peak(int rr, int cc, std::uint64_t cycle) {
    const auto& h = plans_[static_cast<size_t>(rr)].kernel.events[static_cast<size_t>(cc)];
    long long best = -1, at = 0, n = 0, d = 0;
    for (std::size_t i = 0; i < h.size(); ++i) {
      const long long v = std::min(h[i], count_max_);
      if (v > best) best = v, at = static_cast<long long>(i);
      n += static_cast<long long>(i) * v, d += v;
    }
    e_.peak_valid = true;
    e_.peak_code = at, e_.peak_count = best, e_.centroid_num = n, e_.centroid_den = d;
    sb_.expect("histogram peak code", -1, rr, cc, cycle, at, static_cast<long long>(peak_code.read()));
    sb_.expect("histogram peak count", -1, rr, cc, cycle, best, static_cast<long long>(peak_count.read()));
    sb_.expect("centroid numerator", -1, rr, cc, cycle, n, static_cast<long long>(num.read()));
    sb_.expect("centroid denominator", -1, rr, cc, cycle, d, static_cast<long long>(den.read()));
  }

  CosimOptions o_;
  CosimReport& r_;
  CosimScoreboard sb_;
  Setup s_;
  TofSpadRtlShape shape_;
  int cpt_;              // columns of the group (CPT)
  long long count_max_;  // bins saturate at 2^COUNT_BITS - 1
  TofSpadKernel kernel_;
  int block_event_ = 0, block_overflow_ = 0;
  std::vector<RowPlan> plans_;
  long long row_len_ = 0;       // cycles per row (integration + readout)
  long long start_cycle_ = -1;  // cycle in which start_i was high
  std::uint32_t last_phase_ = 0;
  long long phase_cycles_[3] = {0, 0, 0};
  long long events_seen_ = 0;
  std::vector<std::vector<long long>> rtl_events_;  // RTL histograms [row * CPT + column][code]
  std::uint64_t cycle_ = 0;
  std::ofstream record_;
  SpadExpected e_;  // the model's pins of this cycle (trace)
};

// Runs the TDC group RTL VTop, verilated with verilog_parameters(base), against the kernels on
// random setups drawn on `base` (its timing redrawn within the ranges of random_tof_spad_setup, tb/tof_spad/stimulus.h).
// high_rates: the `tdc` target. record_path: per-cycle inputs and RTL outputs for the Icarus
// replay (tb/tof_spad/tof_spad_sequencer_replay_tb.sv).
template <class VTop>
CosimReport run_tof_spad_harness(const CosimOptions& o, const TofSpadConfig& base, bool high_rates,
                                 const std::string& record, const std::string& target) {
  CosimReport r;
  r.target = target;
  VerilatedContext* ctx = cosim_verilator_context(o);
  const TofSpadRtlShape shape = tof_spad_rtl_shape(base, target);
  Setup s = random_tof_spad_rows(base, shape.cpt, (1LL << shape.row_bits) - 1, o.cycles, o.seed, high_rates);
  const sc_core::sc_time period(s.cfg.tdc.lsb_s, sc_core::SC_SEC);
  SpadCosimTop<VTop> top("cosim", o, r, std::move(s), shape, record, period);
  run_cosim_top(top, o.trace_path, period, top.cycle_bound());
  top.finish();
  finish_cosim_report(r, ctx);
  return r;
}

// `rangesim cosim <tof-spad preset>` (tb/common/cosim_child.h): one TDC group of the preset's
// width, VTop verilated at run time with verilog_parameters() of the preset's config.
template <class VTop>
CosimReport run_tof_spad_preset(const ParamSet& preset, const CosimOptions& o) {
  const TofSpadConfig cfg = tof_spad_from_params(preset);
  verilog_parameters(cfg, preset.origin());  // the limits the RTL adds
  return run_tof_spad_harness<VTop>(o, cfg, false, "", preset_target_name(preset));
}

}  // namespace tof_spad_harness

using tof_spad_harness::run_tof_spad_harness;
using tof_spad_harness::run_tof_spad_preset;

}  // namespace rangesim::tb
