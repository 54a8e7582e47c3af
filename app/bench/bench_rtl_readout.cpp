#include "app/bench/bench_rtl_readout.h"

#include <verilated.h>

#include <memory>
#include <stdexcept>
#include <string>
#include <systemc>

#include "Vaddress_search.h"
#include "app/bench/bench_util.h"
#include "golden/frame_timing.h"
#include "rtl/address_search_params.h"

namespace rangesim::app::bench {

namespace {

constexpr int kResetCycles = 3;  // rst high; the RTL's state is random before its first edge
constexpr int kColumns = 375;    // Vaddress_search's act_i width (checked against the config)

struct Schedule {
  long long frame_cycles = 0;  // F
  std::vector<long long> start_in_frame;  // per sampling k-1: cycle of search_start within the frame
};

Schedule schedule(const LsConventionalConfig& cfg) {
  Schedule s;
  const FrameTimingConfig& t = cfg.timing;
  const int N = cfg.multisampling.samplings;
  s.frame_cycles = golden::frame_timing(t, N).frame_cycles;
  const long long P = t.latch_cycles + t.search_cycles + static_cast<long long>(t.addresses_per_sampling) * t.address_bits;
  for (int k = 1; k <= N; ++k) s.start_in_frame.push_back(t.reset_cycles + (k - 1) * P + t.latch_cycles - 1);
  return s;
}

class ReadoutTop : public sc_core::sc_module {
 public:
  sc_core::sc_clock clk;
  sc_core::sc_signal<bool> rst{"rst", true};
  sc_core::sc_signal<bool> start{"start"};
  sc_core::sc_vector<sc_core::sc_signal<sc_dt::sc_bv<kColumns>>> act{"act"};
  sc_core::sc_vector<sc_core::sc_signal<bool>> busy{"busy"}, found{"found"}, addr_valid{"addr_valid"},
      addr_bit{"addr_bit"}, done{"done"};
  std::vector<std::unique_ptr<Vaddress_search>> rtl;

  SC_HAS_PROCESS(ReadoutTop);
  ReadoutTop(sc_core::sc_module_name name, const LsConventionalConfig& cfg, const ReadoutStimulus& stim, sc_core::sc_time period)
      : sc_core::sc_module(name), clk("clk", period), cfg_(cfg), stim_(stim), sched_(schedule(cfg)) {
    rows_ = cfg.pixel.rows;
    N_ = cfg.multisampling.samplings;
    B_ = cfg.search.address_bits;
    act.init(rows_);
    busy.init(rows_), found.init(rows_), addr_valid.init(rows_), addr_bit.init(rows_), done.init(rows_);
    stream_.assign(static_cast<std::size_t>(rows_), {});
    for (int r = 0; r < rows_; ++r) {
      rtl.push_back(std::make_unique<Vaddress_search>(("row" + std::to_string(r)).c_str()));
      Vaddress_search& v = *rtl.back();
      v.clk(clk);
      v.rst(rst);
      v.start_i(start);
      v.act_i(act[r]);
      v.busy_o(busy[r]);
      v.found_o(found[r]);
      v.addr_valid_o(addr_valid[r]);
      v.addr_bit_o(addr_bit[r]);
      v.done_o(done[r]);
    }
    SC_THREAD(stimulus);
    sensitive << clk.posedge_event();
    SC_METHOD(monitor);
    sensitive << clk.negedge_event();
    dont_initialize();
  }

  RtlReadoutResult& result() { return res_; }

 private:
  struct Stream {
    unsigned bits = 0;  // address bits streamed so far in this operation
    int n = 0;          // how many
    int op = 0;         // operations completed by this row
  };

  // Drives the inputs of the cycle that begins at this rising edge.
  void stimulus() {
    for (int i = 0; i < kResetCycles; ++i) wait();
    rst.write(false);
    const int F = static_cast<int>(sched_.frame_cycles);
    for (int f = 0; f < stim_.frames; ++f) {
      for (int c = 0; c < F; ++c) {
        cycle_ = static_cast<long long>(f) * F + c;
        int k = 0;
        for (int j = 0; j < N_; ++j)
          if (sched_.start_in_frame[static_cast<std::size_t>(j)] == c) k = j + 1;
        start.write(k > 0);
        if (k > 0) {
          for (int r = 0; r < rows_; ++r) {
            const systemc::ActivationRow& a = stim_.act[(static_cast<std::size_t>(f) * N_ + (k - 1)) * rows_ + r];
            const auto& w = a.words();
            sc_dt::sc_bv<kColumns> v;
            for (int word = 0; word * 64 < kColumns; ++word) {
              const int width = std::min(64, kColumns - word * 64);
              v.range(word * 64 + width - 1, word * 64) = sc_dt::sc_uint<64>(w[static_cast<std::size_t>(word)]).range(width - 1, 0);
            }
            act[r].write(v);
          }
        }
        wait();
      }
    }
    cycle_ = static_cast<long long>(stim_.frames) * F;
    wait();
    res_.cycles = cycle_;
    sc_core::sc_stop();
  }

  // Mid-cycle: all outputs have settled after the rising edge.
  void monitor() {
    if (cycle_ < 0) return;
    for (int r = 0; r < rows_; ++r) {
      Stream& s = stream_[static_cast<std::size_t>(r)];
      if (addr_valid[r].read()) {
        s.bits = (s.bits << 1) | (addr_bit[r].read() ? 1U : 0U);
        ++s.n;
      }
      if (done[r].read()) {
        ReadoutTxn t;
        t.frame = s.op / N_;
        t.sampling = s.op % N_ + 1;
        t.row = r;
        t.found = found[r].read();
        const unsigned mask = (1U << B_) - 1;
        if (s.n == 2 * B_) t.left = static_cast<int>((s.bits >> B_) & mask), t.right = static_cast<int>(s.bits & mask);
        t.done_cycle = cycle_;
        txns_.push_back(t);
        s = Stream{0, 0, s.op + 1};
      }
    }
  }

 public:
  // Transactions ordered by (frame, sampling, row).
  std::vector<ReadoutTxn> ordered() const {
    std::vector<ReadoutTxn> out(txns_);
    std::stable_sort(out.begin(), out.end(), [](const ReadoutTxn& a, const ReadoutTxn& b) {
      return std::tie(a.frame, a.sampling, a.row) < std::tie(b.frame, b.sampling, b.row);
    });
    return out;
  }

 private:
  LsConventionalConfig cfg_;
  const ReadoutStimulus& stim_;
  Schedule sched_;
  int rows_ = 0, N_ = 0, B_ = 0;
  long long cycle_ = -1;          // cycle since reset release of the current cycle (-1: in reset)
  std::vector<Stream> stream_;    // per row
  std::vector<ReadoutTxn> txns_;  // in completion order
  RtlReadoutResult res_;
};

}  // namespace

long long readout_start_cycle(const LsConventionalConfig& cfg, int frame, int sampling) {
  const Schedule s = schedule(cfg);
  return static_cast<long long>(frame) * s.frame_cycles + s.start_in_frame[static_cast<std::size_t>(sampling - 1)];
}

std::vector<ReadoutTxn> model_readout(const LsConventionalConfig& cfg, const ReadoutStimulus& stim) {
  const systemc::AddressSearchKernel k(cfg.search, cfg.timing.search_cycles);
  const int N = cfg.multisampling.samplings, R = cfg.pixel.rows;
  std::vector<ReadoutTxn> out;
  out.reserve(stim.act.size());
  for (int f = 0; f < stim.frames; ++f)
    for (int s = 1; s <= N; ++s) {
      const long long start = readout_start_cycle(cfg, f, s);
      for (int r = 0; r < R; ++r) {
        const systemc::AddressSearchResult e = k.evaluate(stim.act[(static_cast<std::size_t>(f) * N + (s - 1)) * R + r]);
        out.push_back({f, s, r, e.found, e.left, e.right, start + e.done_cycle});
      }
    }
  return out;
}

RtlReadoutResult run_rtl_readout(const LsConventionalConfig& cfg, const ReadoutStimulus& stim) {
  const auto& p = rangesim::rtl::kAddressSearchDefault;
  if (cfg.pixel.columns != kColumns || p.columns != kColumns || cfg.search.address_bits != p.address_bits ||
      cfg.timing.search_cycles != p.search_cycles)
    throw std::invalid_argument("bench: the verilated Vaddress_search is built for 375 columns, " +
                                std::to_string(p.address_bits) + " address bits, " + std::to_string(p.search_cycles) +
                                " search cycles; the preset differs");
  Verilated::defaultContextp()->fatalOnError(false);
  const sc_core::sc_time period(1.0 / cfg.timing.clock_Hz, sc_core::SC_SEC);
  const auto t0 = Clock::now();
  ReadoutTop top("readout", cfg, stim, period);
  sc_core::sc_start(sc_core::SC_ZERO_TIME);
  const double elaboration_s = seconds_since(t0);
  const auto t1 = Clock::now();
  const double c1 = cpu_now();
  const long long limit = kResetCycles + 4 + static_cast<long long>(stim.frames) * schedule(cfg).frame_cycles;
  sc_core::sc_start(period * static_cast<double>(limit));
  RtlReadoutResult r = top.result();
  r.wall_s = seconds_since(t1);
  r.cpu_s = cpu_now() - c1;
  r.elaboration_s = elaboration_s;
  r.txns = top.ordered();
  r.assertion_failed = Verilated::defaultContextp()->gotError();
  r.sc_errors = static_cast<long long>(sc_core::sc_report_handler::get_count(sc_core::SC_ERROR));
  return r;
}

}  // namespace rangesim::app::bench
