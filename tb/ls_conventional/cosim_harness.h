#pragma once
// Co-simulation harness of the ls-conventional readout (see cosim.h), templated on the verilated
// class so that one harness serves the built-in instances (tb/ls_conventional/cosim.cpp) and the
// instances verilated at run time for a preset (tb/common/rtl_build.h). Everything about the
// instance comes from its LsConventionalConfig: the RTL was verilated with
// verilog_parameters(config) (tb/ls_conventional/verilog_parameters.h).
//
// Timing: both views change their outputs only just after a rising edge, so one SC_METHOD on the
// falling edge samples both mid-cycle. The model kernel is ticked on the rising edge, and the
// comparator inputs it produces for the new cycle (pixel reset, a new sampling's latch) are
// written right after that edge, so the RTL samples them at the edge that ends the cycle, as
// the model's address searches do. Reset: rst is high for the first kResetEdges edges; the model
// is reset at the last of them, and cycle 0 of both is the period after it.
#include <verilated.h>
#include <verilated_vcd_sc.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <memory>
#include <random>
#include <sstream>
#include <string>
#include <systemc>
#include <vector>

#include "core/ls_conventional/config.h"
#include "golden/common/row_model.h"
#include "golden/ls_conventional/frame_timing.h"
#include "golden/ls_conventional/multisampling.h"
#include "systemc/ls_conventional/sensor_kernel.h"
#include "core/params.h"
#include "tb/common/cosim_run.h"
#include "tb/common/cosim_child.h"
#include "tb/common/cosim_ports.h"
#include "tb/common/cosim_scoreboard.h"
#include "tb/ls_conventional/stimulus.h"
#include "tb/common/verilog_parameters.h"
#include "tb/ls_conventional/readout_ports.h"
#include "tb/ls_conventional/cosim.h"
#include "tb/ls_conventional/verilog_parameters.h"

namespace rangesim::tb {
namespace ls_conventional_harness {

using rangesim::systemc::CentreProcessorPins;
using rangesim::systemc::FrameStimulus;
using rangesim::systemc::LsConventionalSensorKernel;
using rangesim::systemc::MultisamplingSequencerPins;
using rangesim::systemc::ReadoutPhase;

constexpr int kResetEdges = 3;  // rst high; before its first edge the RTL state is random

struct StreamRecord {  // one row's address stream in one sampling, one side
  int bits = 0;
  std::uint64_t value = 0;
  long long first_cycle = -1, last_cycle = -1;
};

template <class VTop>
class LsCosimTop : public sc_core::sc_module {
 public:
  sc_core::sc_clock clk;
  sc_core::sc_signal<bool> rst{"rst", true};
  VTop rtl{"rtl"};
  LsReadoutSignals<VTop> sig;  // the RTL's ports (tb/ls_conventional/readout_ports.h)

  SC_HAS_PROCESS(LsCosimTop);
  LsCosimTop(sc_core::sc_module_name name, const LsConventionalCosimOptions& o, const std::string& target,
             const LsConventionalConfig& cfg, const systemc::SensorKernelOptions& kopt, sc_core::sc_time period)
      : sc_core::sc_module(name),
        clk("clk", period),
        o_(o),
        rows_(cfg.pixel.rows),
        columns_(cfg.pixel.columns),
        address_bits_(cfg.search.address_bits),
        cfg_(cfg),
        noise_free_(!kopt.pixel.noise.any()),
        kernel_(cfg, kopt, random_ls_conventional_scenes(o.seed, rows_, columns_)),
        fields_(cfg),
        board_(report_),
        rec_{std::vector<StreamRecord>(static_cast<std::size_t>(rows_)),
             std::vector<StreamRecord>(static_cast<std::size_t>(rows_))} {
    sig.bind(rtl, clk, rst);
    report_.target = target;
    fault_frame_ = o.frames > 1 ? 1 : 0;
    if (!o.record_stimulus_path.empty()) stim_out_.open(o.record_stimulus_path);
    if (!o.record_outputs_path.empty()) out_out_.open(o.record_outputs_path);
    SC_METHOD(on_posedge);
    sensitive << clk.posedge_event();
    dont_initialize();
    SC_METHOD(on_negedge);
    sensitive << clk.negedge_event();
    dont_initialize();
  }

  CosimReport& report() { return report_; }

  // The clock-level model's pins of every cycle, beside the RTL's in the trace
  // (tb/common/cosim_run.h): the sequencer and each row's centre processor, as the scoreboard
  // sees them at the falling edge.
  void trace_expected(systemc::Waveform& w) {
    tracing_ = true;
    expected_centre_.assign(static_cast<std::size_t>(rows_), {});
    systemc::Waveform::ValueNames phases;
    for (int p = 0; p < systemc::kReadoutPhases; ++p)
      phases.push_back({p, systemc::readout_phase_name(static_cast<systemc::ReadoutPhase>(p))});
    w.add(expected_phase_, "sequencer", "phase", phases);
    w.add(expected_seq_.pix_reset, "sequencer", "pix_reset");
    w.add(expected_seq_.latch, "sequencer", "latch");
    w.add(expected_seq_.search_start, "sequencer", "search_start");
    w.add(expected_seq_.frame_done, "sequencer", "frame_done");
    w.add(expected_seq_.sampling, "sequencer", "sampling");
    for (int r = 0; r < rows_; ++r) {
      const std::string row = "row" + std::to_string(r);
      const CentreProcessorPins& c = expected_centre_[static_cast<std::size_t>(r)];
      w.add(c.valid, row, "centre_valid");
      w.add(c.centre_q, row, "centre_q");
      w.add(c.sum, row, "sum");
      w.add(c.count, row, "count");
    }
  }
  long long frames_done() const { return frames_done_; }
  int recorded_cycles() const { return recorded_; }

  void finish() {
    // A stream still open at the end (the run stopped mid-sampling) is compared as it is.
    compare_streams(kernel_.sequencer().pins());
    for (const std::string& e : kernel_.errors()) add({"model_protocol", -1, -1, -1, 0, "no error", e});
  }

 private:
  // ---- stimulus ----
  void on_posedge() {
    const long long e = edges_++;
    if (e < kResetEdges - 1) return;
    if (e == kResetEdges - 1) {
      kernel_.reset();
      rst.write(false);
    } else {
      kernel_.tick();
    }
    const auto& px = kernel_.pixels();
    const std::pair<std::uint64_t, int> key{px.frame(), px.sampling()};
    if (!driven_ || key != cmp_key_) {
      driven_ = true;
      cmp_key_ = key;
      std::vector<std::uint32_t> words(static_cast<std::size_t>((rows_ * columns_ + 31) / 32), 0U);
      for (int r = 0; r < rows_; ++r) {
        const auto& row = px.row(r);
        for (int c = row.first(); c >= 0 && c <= row.last(); ++c) {
          if (!row.test(c)) continue;
          const long long b = static_cast<long long>(r) * columns_ + c;
          words[static_cast<std::size_t>(b / 32)] |= 1U << (b % 32);
        }
      }
      PortData<decltype(rtl.cmp_i)> v{};
      port_from_words(words, v);
      sig.cmp.write(v);
      cmp_words_ = std::move(words);
    }
  }

  // ---- scoreboard ----
  void add(CosimMismatch m) { board_.add(std::move(m)); }

  static std::string seq_string(const MultisamplingSequencerPins& s) {
    std::ostringstream o;
    o << "phase " << systemc::readout_phase_name(s.phase) << " pix_reset " << s.pix_reset << " latch " << s.latch
      << " search_start " << s.search_start << " frame_done " << s.frame_done << " sampling " << s.sampling << " frame "
      << s.frame;
    return o.str();
  }
  static std::string centre_string(const CentreProcessorPins& c) {
    std::ostringstream o;
    o << "valid " << c.valid << " centre " << c.centre_px() << " px (Q.8 " << c.centre_q << ") sum " << c.sum << " n "
      << c.count;
    return o.str();
  }
  std::string stream_string(const StreamRecord& s) const {
    if (s.bits == 0) return "no stream";
    std::ostringstream o;
    const std::uint64_t mask = low_mask(address_bits_);
    if (s.bits == 2 * address_bits_)
      o << "left " << ((s.value >> address_bits_) & mask) << " right " << (s.value & mask);
    else
      o << s.bits << " bits 0x" << std::hex << s.value << std::dec;
    o << " (cycles " << s.first_cycle << ".." << s.last_cycle << ")";
    return o.str();
  }

  void compare_streams(const MultisamplingSequencerPins& sp) {
    for (int r = 0; r < rows_; ++r) {
      StreamRecord& m = rec_[0][static_cast<std::size_t>(r)];
      StreamRecord& g = rec_[1][static_cast<std::size_t>(r)];
      if (m.bits == 0 && g.bits == 0) continue;
      board_.count("address", 2);  // left and right address
      if (m.bits != g.bits || m.value != g.value || m.first_cycle != g.first_cycle || m.last_cycle != g.last_cycle) {
        const long long col = m.bits == 2 * address_bits_
                                  ? static_cast<long long>((m.value >> address_bits_) & low_mask(address_bits_))
                                  : -1;
        add({"address", static_cast<long long>(sp.frame), r, col,
             static_cast<std::uint64_t>(m.bits ? m.last_cycle : g.last_cycle), stream_string(m), stream_string(g)});
      }
      m = {};
      g = {};
    }
  }

  void on_negedge() {
    const long long period = edges_ - 1;
    if (stim_out_.is_open()) {
      std::vector<std::uint32_t> w = cmp_words_;
      const int width = rows_ * columns_ + 1;
      w.resize(static_cast<std::size_t>((width + 31) / 32), 0U);
      if (rst.read()) w[static_cast<std::size_t>((width - 1) / 32)] |= 1U << ((width - 1) % 32);
      stim_out_ << hex_words(w, width) << '\n';
      ++recorded_;
    }
    if (period < kResetEdges - 1) return;
    const long long cycle = period - (kResetEdges - 1);
    report_.cycles = static_cast<std::uint64_t>(cycle + 1);
    const MultisamplingSequencerPins sp = kernel_.sequencer().pins();
    const long long frame_no = static_cast<long long>(sp.frame);
    if (tracing_) {
      expected_seq_ = sp;
      expected_phase_ = static_cast<int>(sp.phase);
      for (int r = 0; r < rows_; ++r) expected_centre_[static_cast<std::size_t>(r)] = kernel_.centre(r).pins();
    }

    if (out_out_.is_open()) {
      const auto& g = sig;
      out_out_ << port_hex(g.phase.read(), 3) << ' ' << port_hex(g.pix_reset.read(), 1) << ' '
               << port_hex(g.latch.read(), 1) << ' ' << port_hex(g.search_start.read(), 1) << ' '
               << port_hex(g.frame_done.read(), 1) << ' ' << port_hex(g.sampling.read(), fields_.sampling) << ' '
               << port_hex(g.frame.read(), 32) << ' ' << port_hex(g.busy.read(), rows_) << ' '
               << port_hex(g.addr_valid.read(), rows_) << ' ' << port_hex(g.addr_bit.read(), rows_) << ' '
               << port_hex(g.centre_valid.read(), rows_) << ' ' << port_hex(g.centre_q.read(), rows_ * fields_.centre)
               << ' ' << port_hex(g.sum.read(), rows_ * fields_.sum) << ' '
               << port_hex(g.count.read(), rows_ * fields_.count) << '\n';
    }

    // Sequencer pins, every cycle.
    const MultisamplingSequencerPins gp = sig.sequencer_pins(fields_);
    MultisamplingSequencerPins mp = sp;
    mp.frame &= 0xffffffffULL;  // frame_o is 32 bits wide (its wrap is an RTL assertion)
    if (!(gp == mp))
      add({"sequencer", frame_no, -1, -1, static_cast<std::uint64_t>(cycle), seq_string(mp), seq_string(gp)});

    // Rows: busy every cycle, address streams per sampling.
    const auto& av = sig.addr_valid.read();
    const auto& ab = sig.addr_bit.read();
    const auto& bz = sig.busy.read();
    for (int r = 0; r < rows_; ++r) {
      const auto m = kernel_.search(r).pins();
      const bool g_busy = port_bit(bz, r);
      bool g_valid = port_bit(av, r), g_bit = port_bit(ab, r);
      // Faults act on what the scoreboard sees of the RTL.
      if (o_.inject_fault == "address_bit_flip" && !report_.fault_injected && frame_no >= fault_frame_ && g_valid) {
        g_bit = !g_bit;
        report_.fault_injected = true;
        report_.fault_site =
            site(frame_no, r, cycle, "stream bit " + std::to_string(rec_[1][static_cast<std::size_t>(r)].bits));
      }
      if (o_.inject_fault == "dropped_row") {
        if (drop_row_ < 0 && frame_no >= fault_frame_ && g_valid) {
          drop_row_ = r;
          drop_frame_ = frame_no;
          report_.fault_injected = true;
          report_.fault_site = site(frame_no, r, cycle, "row's streams and centre dropped for the frame");
        }
        if (r == drop_row_ && frame_no == drop_frame_) g_valid = g_bit = false;
      }
      if (m.busy != g_busy)
        add({"busy", frame_no, r, -1, static_cast<std::uint64_t>(cycle), std::to_string(m.busy),
             std::to_string(g_busy)});
      const bool valid[2] = {m.addr_valid, g_valid};
      const bool bit[2] = {m.addr_bit, g_bit};
      for (int s = 0; s < 2; ++s) {
        if (!valid[s]) continue;
        StreamRecord& rec = rec_[s][static_cast<std::size_t>(r)];
        if (rec.bits == 0) rec.first_cycle = cycle;
        rec.last_cycle = cycle;
        rec.value = (rec.value << 1) | (bit[s] ? 1U : 0U);
        ++rec.bits;
      }
    }
    // End of a sampling's stream phase in the model's schedule: compare the records.
    if (sp.phase == ReadoutPhase::AddressStream &&
        kernel_.sequencer().pins_at(kernel_.sequencer().cycle() + 1).phase != ReadoutPhase::AddressStream)
      compare_streams(sp);

    if (sp.frame_done) check_frame(sp, cycle);
  }

  std::string site(long long frame_no, int row, long long cycle, const std::string& what) const {
    return "frame " + std::to_string(frame_no) + " row " + std::to_string(row) + " cycle " + std::to_string(cycle) +
           ": " + what;
  }

  void check_frame(const MultisamplingSequencerPins& sp, long long cycle) {
    const long long frame_no = static_cast<long long>(sp.frame);
    const FrameStimulus& stim = kernel_.pixels().stimulus();
    for (int r = 0; r < rows_; ++r) {
      const CentreProcessorPins m = kernel_.centre(r).pins();
      CentreProcessorPins g = sig.centre_pins(fields_, r);
      if (o_.inject_fault == "dropped_row" && r == drop_row_ && frame_no == drop_frame_) g = {};
      if (o_.inject_fault == "centre_off_by_one" && !report_.fault_injected && frame_no >= fault_frame_ && g.valid) {
        g.centre_q += 1;
        report_.fault_injected = true;
        report_.fault_site = site(frame_no, r, cycle, "centre + 1 LSB");
      }
      board_.count("centre");
      if (m != g)
        add({"centre", frame_no, r, -1, static_cast<std::uint64_t>(cycle), centre_string(m), centre_string(g)});
      // Golden: noise-free, the edge-centre estimate of the same row is exact.
      if (noise_free_) {
        const auto& il = stim.rows[static_cast<std::size_t>(r)];
        const golden::CentreEstimate ge =
            golden::direct_estimate(golden::make_row_model(cfg_, il.signal_V, il.background_V), il.centre_px);
        ++report_.golden_checks;
        const bool ok = ge.detected == g.valid && (!g.valid || std::abs(ge.centre_px - g.exact_centre_px()) < 1e-9);
        if (!ok) {
          std::ostringstream e, a;
          e << (ge.detected ? "centre " + std::to_string(ge.centre_px) + " px" : std::string("no detection"));
          a << (g.valid ? "centre " + std::to_string(g.exact_centre_px()) + " px (sum/2n)"
                        : std::string("no detection"));
          add({"golden_centre", frame_no, r, -1, static_cast<std::uint64_t>(cycle), e.str(), a.str()});
        }
      }
    }
    ++frames_done_;
    if (o_.progress) o_.progress(frames_done_);
    if (frames_done_ >= o_.frames) sc_core::sc_stop();
  }

  static std::string hex_words(const std::vector<std::uint32_t>& w, int width) {
    static const char* digits = "0123456789abcdef";
    std::string s;
    for (int d = (width + 3) / 4 - 1; d >= 0; --d) {
      const int b = 4 * d;
      const std::uint32_t nib = (w[static_cast<std::size_t>(b / 32)] >> (b % 32)) & 0xfU;
      s.push_back(digits[nib]);
    }
    return s;
  }

  LsConventionalCosimOptions o_;
  int rows_, columns_, address_bits_;  // array and address width of the RTL instance (its config)
  LsConventionalConfig cfg_;
  bool noise_free_;
  LsConventionalSensorKernel kernel_;
  LsReadoutFields fields_;  // RTL field widths: sampling, centre Q.8, sum, count
  CosimReport report_;
  CosimScoreboard board_;                    // records into report_ (no SC reports: see cosim.h)
  std::vector<StreamRecord> rec_[2];         // per row, [0] model, [1] RTL
  long long edges_ = 0;                      // rising edges so far
  bool driven_ = false;                      // cmp written at least once
  std::pair<std::uint64_t, int> cmp_key_{};  // (frame, sampling) of the pixel array when last written
  std::vector<std::uint32_t> cmp_words_;     // cmp_i as last written
  long long fault_frame_ = 1;                // faults go into this frame access or later
  int drop_row_ = -1;
  // trace_expected(): the model's pins of the current cycle, traced by reference.
  bool tracing_ = false;
  MultisamplingSequencerPins expected_seq_;
  int expected_phase_ = 0;
  std::vector<CentreProcessorPins> expected_centre_;
  long long drop_frame_ = -1;
  long long frames_done_ = 0;
  std::ofstream stim_out_, out_out_;
  int recorded_ = 0;
};

// Runs the readout RTL VTop, verilated with verilog_parameters(cfg), beside the clock-level
// model of cfg; `target` names the report.
template <class VTop>
LsConventionalCosimResult run_ls_conventional_harness(const LsConventionalCosimOptions& o,
                                                      const LsConventionalConfig& cfg, const std::string& target) {
  const auto t0 = std::chrono::steady_clock::now();
  VerilatedContext* ctx = cosim_verilator_context(o.seed, o.trace_path);
  systemc::SensorKernelOptions kopt;
  kopt.event_skipping = false;  // cycle by cycle, as the sc_modules run it
  kopt.pixel.seed = o.seed;
  if (o.seed % 2 == 1) kopt.pixel.noise = systemc::PixelNoiseConfig::none();  // odd: noise-free, golden-exact
  const sc_core::sc_time period(1.0 / cfg.timing.clock_Hz, sc_core::SC_SEC);
  LsCosimTop<VTop> top("cosim", o, target, cfg, kopt, period);

  const long long fc = rangesim::frame_cycles(cfg.timing, cfg.multisampling.samplings);
  // Bounded: the run stops itself after the last frame; this is the safety net.
  run_cosim_top(top, o.trace_path, period, kResetEdges + 2 + fc * (o.frames + 1));
  top.finish();

  LsConventionalCosimResult res;
  res.report = top.report();
  res.frames = top.frames_done();
  if (res.frames < o.frames) {  // the schedule stalled: nothing else would say so
    CosimScoreboard(res.report)
        .add({"run", res.frames, -1, -1, res.report.cycles, std::to_string(o.frames) + " frame accesses",
              std::to_string(res.frames) + " within the cycle bound"});
  }
  res.report.rtl_assertions_failed = ctx->gotError() ? 1 : 0;
  if (res.report.rtl_assertions_failed) CosimScoreboard(res.report).add(rtl_assertion_mismatch(res.report.cycles));
  res.report.sc_errors = static_cast<int>(sc_core::sc_report_handler::get_count(sc_core::SC_ERROR));
  res.recorded_cycles = top.recorded_cycles();
  res.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return res;
}

}  // namespace ls_conventional_harness

using ls_conventional_harness::run_ls_conventional_harness;

// `rangesim cosim <preset.toml>` (tb/common/cosim_child.h): the readout of the preset's own
// architecture, VTop verilated at run time with verilog_parameters() of the preset's config.
template <class VTop>
CosimReport run_ls_conventional_preset(const ParamSet& preset, const CosimOptions& o) {
  const LsConventionalConfig cfg = ls_conventional_from_params(preset);
  verilog_parameters(cfg, preset.origin());  // the cross-key checks the RTL adds
  return run_ls_conventional_harness<VTop>(ls_conventional_options(o, cfg), cfg, preset_target_name(preset)).report;
}

}  // namespace rangesim::tb
