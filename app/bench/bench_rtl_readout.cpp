#include "app/bench/bench_rtl_readout.h"

#include <verilated.h>

#include <algorithm>
#include <stdexcept>
#include <string>
#include <systemc>
#include <tuple>

#include "Vls_conventional_readout.h"
#include "app/bench/bench_util.h"
#include "golden/ls_conventional/frame_timing.h"
#include "tb/common/cosim_ports.h"
#include "tb/common/instance_preset.h"
#include "tb/ls_conventional/readout_ports.h"
#include "tb/ls_conventional/verilog_parameters.h"

namespace rangesim::app::bench {

namespace {

using tb::port_bit;
using tb::port_field;
using tb::PortData;

constexpr int kResetCycles = 3;  // rst high; the RTL's state is random before its first edge

struct Schedule {
  long long frame_cycles = 0;             // F
  std::vector<long long> latch_in_frame;  // per sampling k-1: first latch cycle within the frame
  std::vector<long long> start_in_frame;  // per sampling k-1: search start (last latch cycle)
};

Schedule schedule(const LsConventionalConfig& cfg) {
  Schedule s;
  const FrameTimingConfig& t = cfg.timing;
  const int N = cfg.multisampling.samplings;
  s.frame_cycles = rangesim::frame_cycles(t, N);
  const long long P =
      t.latch_cycles + t.search_cycles + static_cast<long long>(t.addresses_per_sampling) * t.address_bits;
  for (int k = 1; k <= N; ++k) {
    s.latch_in_frame.push_back(t.reset_cycles + (k - 1) * P);
    s.start_in_frame.push_back(t.reset_cycles + (k - 1) * P + t.latch_cycles - 1);
  }
  return s;
}

// The verilated Vls_conventional_readout must be the preset's readout: the Verilog parameters of
// its config must be those of the instance preset it was verilated from
// (rtl/ls_conventional/instances/full.toml).
void check_instance(const LsConventionalConfig& cfg) {
  const ParamSet built = tb::instance_preset("Vls_conventional_readout");
  const tb::VerilogParameters want = tb::verilog_parameters(cfg, "bench");
  const tb::VerilogParameters have = tb::verilog_parameters(ls_conventional_from_params(built), built.origin());
  if (want != have)
    throw std::invalid_argument("bench: the preset's readout (" + tb::parameters_text(want) +
                                ") differs from the verilated one (" + tb::parameters_text(have) + ", " +
                                built.origin() + ")");
}

class ReadoutTop : public sc_core::sc_module {
 public:
  sc_core::sc_clock clk;
  sc_core::sc_signal<bool> rst{"rst", true};
  Vls_conventional_readout rtl{"rtl"};
  tb::LsReadoutSignals<Vls_conventional_readout> sig;  // the harness's ports (tb/ls_conventional/readout_ports.h)

  SC_HAS_PROCESS(ReadoutTop);
  ReadoutTop(sc_core::sc_module_name name, const LsConventionalConfig& cfg, const ReadoutStimulus& stim,
             sc_core::sc_time period)
      : sc_core::sc_module(name), clk("clk", period), frames_(stim.frames), sched_(schedule(cfg)), fields_(cfg) {
    rows_ = cfg.pixel.rows;
    columns_ = cfg.pixel.columns;
    N_ = cfg.multisampling.samplings;
    B_ = cfg.search.address_bits;
    sig.bind(rtl, clk, rst);
    build_cmp_values(stim);
    open_.assign(static_cast<std::size_t>(rows_), {});
    SC_THREAD(stimulus);
    sensitive << clk.posedge_event();
    SC_METHOD(monitor);
    sensitive << clk.negedge_event();
    dont_initialize();
  }

  long long cycles() const { return cycles_; }
  const std::vector<systemc::FrameResult>& frames() const { return frame_results_; }
  // Streams ordered by (frame, sampling, row).
  std::vector<StreamTxn> streams() const {
    std::vector<StreamTxn> out(streams_);
    std::stable_sort(out.begin(), out.end(), [](const StreamTxn& a, const StreamTxn& b) {
      return std::tie(a.frame, a.sampling, a.row) < std::tie(b.frame, b.sampling, b.row);
    });
    return out;
  }

 private:
  // cmp_i of every (frame, sampling), built before the clock runs so the timed run is the RTL's.
  void build_cmp_values(const ReadoutStimulus& stim) {
    const std::size_t n_words = (static_cast<std::size_t>(rows_) * columns_ + 31) / 32;
    std::vector<std::uint32_t> w;
    cmp_values_.resize(static_cast<std::size_t>(frames_) * N_);
    for (std::size_t fk = 0; fk < cmp_values_.size(); ++fk) {
      w.assign(n_words, 0U);
      for (int r = 0; r < rows_; ++r) {
        const auto& words = stim.act[fk * rows_ + static_cast<std::size_t>(r)].words();
        for (std::size_t i = 0; i < words.size(); ++i)
          for (std::uint64_t bits = words[i]; bits != 0; bits &= bits - 1) {
            const long long b =
                static_cast<long long>(r) * columns_ + static_cast<long long>(i) * 64 + __builtin_ctzll(bits);
            w[static_cast<std::size_t>(b / 32)] |= 1U << (b % 32);
          }
      }
      tb::port_from_words(w, cmp_values_[fk]);
    }
  }

  // Drives the inputs of the cycle that begins at this rising edge: the comparator decisions
  // of sampling k from its first latch cycle on (the RTL reads cmp_i only in latch cycles).
  void stimulus() {
    for (int i = 0; i < kResetCycles; ++i) wait();
    rst.write(false);
    const long long F = sched_.frame_cycles;
    for (int f = 0; f < frames_; ++f) {
      for (long long c = 0; c < F; ++c) {
        cycle_ = f * F + c;
        for (int k = 0; k < N_; ++k)
          if (sched_.latch_in_frame[static_cast<std::size_t>(k)] == c)
            sig.cmp.write(cmp_values_[static_cast<std::size_t>(f) * N_ + static_cast<std::size_t>(k)]);
        wait();
      }
    }
    cycle_ = frames_ * F;
    wait();
    cycles_ = cycle_;
    sc_core::sc_stop();
  }

  struct Open {  // a row's stream in progress
    int bits = 0;
    unsigned value = 0;
    int frame = 0, sampling = 0;
    long long first_cycle = 0, last_cycle = 0;
  };

  void close(int r, Open& s) {
    const unsigned mask = (1U << B_) - 1;
    StreamTxn t{s.frame, s.sampling, r, s.bits, 0, 0, s.first_cycle, s.last_cycle};
    if (s.bits == 2 * B_) t.left = static_cast<int>((s.value >> B_) & mask), t.right = static_cast<int>(s.value & mask);
    streams_.push_back(t);
    s = Open{};
    --n_open_;
  }

  // Mid-cycle: every output has settled after the rising edge.
  void monitor() {
    if (cycle_ < 0) return;
    const auto& av = sig.addr_valid.read();
    bool any = n_open_ > 0;
    for (int i = 0; !any && i < (rows_ + 31) / 32; ++i) any = av.get_word(i) != 0;
    if (any) {
      const auto& ab = sig.addr_bit.read();
      const int f = static_cast<int>(port_field(sig.frame.read(), 0, 32)),
                k = static_cast<int>(port_field(sig.sampling.read(), 0, 8));
      for (int r = 0; r < rows_; ++r) {
        Open& s = open_[static_cast<std::size_t>(r)];
        const bool v = port_bit(av, r);
        if (!v) {
          if (s.bits > 0) close(r, s);  // a stream cut short
          continue;
        }
        if (s.bits == 0) s.first_cycle = cycle_, s.frame = f, s.sampling = k, ++n_open_;
        s.value = (s.value << 1) | (port_bit(ab, r) ? 1U : 0U);
        s.last_cycle = cycle_;
        if (++s.bits == 2 * B_) close(r, s);
      }
    }
    if (sig.frame_done.read()) {
      systemc::FrameResult fr;
      fr.frame = port_field(sig.frame.read(), 0, 32);
      fr.end_cycle = cycle_ + 1;
      fr.rows.resize(static_cast<std::size_t>(rows_));
      for (int r = 0; r < rows_; ++r) fr.rows[static_cast<std::size_t>(r)] = sig.centre_pins(fields_, r);
      frame_results_.push_back(std::move(fr));
    }
  }

  int frames_ = 0;
  Schedule sched_;
  int rows_ = 0, columns_ = 0, N_ = 0, B_ = 0;
  tb::LsReadoutFields fields_;                             // RTL field widths: sampling, centre Q.8, sum, count
  std::vector<PortData<decltype(rtl.cmp_i)>> cmp_values_;  // per (frame, sampling)
  long long cycle_ = -1;  // cycle since reset release of the current cycle (-1: in reset)
  long long cycles_ = 0;
  std::vector<Open> open_;  // per row
  int n_open_ = 0;
  std::vector<StreamTxn> streams_;  // in completion order
  std::vector<systemc::FrameResult> frame_results_;
};

}  // namespace

std::vector<StreamTxn> model_streams(const LsConventionalConfig& cfg, const ReadoutStimulus& stim) {
  const systemc::AddressSearchKernel k(cfg.search, cfg.timing.search_cycles);
  const Schedule sched = schedule(cfg);
  const int N = cfg.multisampling.samplings, R = cfg.pixel.rows, B = cfg.search.address_bits;
  std::vector<StreamTxn> out;
  for (int f = 0; f < stim.frames; ++f)
    for (int s = 1; s <= N; ++s) {
      const long long start = f * sched.frame_cycles + sched.start_in_frame[static_cast<std::size_t>(s - 1)];
      for (int r = 0; r < R; ++r) {
        const systemc::AddressSearchResult e =
            k.evaluate(stim.act[(static_cast<std::size_t>(f) * N + (s - 1)) * R + r]);
        if (!e.found) continue;  // nothing streamed
        out.push_back({f, s, r, 2 * B, e.left, e.right, start + e.done_cycle - 2 * B + 1, start + e.done_cycle});
      }
    }
  return out;
}

RtlReadoutResult run_rtl_readout(const LsConventionalConfig& cfg, const ReadoutStimulus& stim) {
  check_instance(cfg);
  Verilated::defaultContextp()->fatalOnError(false);
  const sc_core::sc_time period(1.0 / cfg.timing.clock_Hz, sc_core::SC_SEC);
  const auto t0 = Clock::now();
  ReadoutTop top("readout", cfg, stim, period);
  sc_core::sc_start(sc_core::SC_ZERO_TIME);
  RtlReadoutResult r;
  r.elaboration_s = seconds_since(t0);
  const auto t1 = Clock::now();
  const double c1 = cpu_now();
  const long long limit = kResetCycles + 4 + static_cast<long long>(stim.frames) * schedule(cfg).frame_cycles;
  sc_core::sc_start(period * static_cast<double>(limit));
  r.wall_s = seconds_since(t1);
  r.cpu_s = cpu_now() - c1;
  r.cycles = top.cycles();
  r.streams = top.streams();
  r.frames = top.frames();
  r.assertion_failed = Verilated::defaultContextp()->gotError();
  r.sc_errors = static_cast<long long>(sc_core::sc_report_handler::get_count(sc_core::SC_ERROR));
  return r;
}

}  // namespace rangesim::app::bench
