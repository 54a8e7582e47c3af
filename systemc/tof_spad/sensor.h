#pragma once
// Thin sc_module around TofSpadKernel: a clocked sequencer thread that, row by row, runs the
// kernel's event-driven integration and waits the integration's cycles (laser STARTs x Np), then
// streams the row's histogram memory out word by word (one word per cycles_per_word clocks).
// Measured cycles come from the simulated time; results must equal the bare kernel's.
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <systemc>
#include <vector>

#include "systemc/common/simulate_entry.h"
#include "systemc/tof_spad/sensor_kernel.h"

namespace rangesim::systemc::spad {

class TofSpadSensor : public sc_core::sc_module {
 public:
  sc_core::sc_out<int> row_o{"row_o"};                 // row connected to the TDCs
  sc_core::sc_out<int> phase_o{"phase_o"};             // 0 idle, 1 laser cycles, 2 histogram readout
  sc_core::sc_out<bool> word_valid_o{"word_valid_o"};  // a histogram word is on word_o
  sc_core::sc_out<std::uint32_t> word_o{"word_o"};     // histogram word (event count, saturated)

  // What the trace shows of the TDC groups of the traced pixels: every timed avalanche at its
  // time (START + code x LSB), what the TDC made of it, and the histogram write it caused.
  // The integration is event driven (no free-running clock: ~1e8 cycles per row); the laser
  // cycle of each hit is its START count.
  struct GroupProbe {
    int group = 0;                       // TDC group (columns group x cpt ..)
    sc_core::sc_signal<bool> hit;        // an avalanche reached the TDC (one LSB pulse)
    sc_core::sc_signal<int> hit_column;  // its pixel's column
    sc_core::sc_signal<int> code;        // its TDC code
    sc_core::sc_signal<int> result;      // 1 event, 2 overflow, 3 lost (TDC busy)
  };
  struct PixelProbe {
    TracePixel at;
    sc_core::sc_signal<bool> avalanche;  // this pixel's timed avalanches (one LSB pulse)
  };
  sc_core::sc_signal<long long> laser_cycle{"laser_cycle"};  // START count of the latest traced hit
  sc_core::sc_signal<bool> write{"write"};                   // histogram write (an event)
  sc_core::sc_signal<int> write_column{"write_column"};      // its pixel's column
  sc_core::sc_signal<int> write_code{"write_code"};          // its code (histogram bin)
  sc_core::sc_signal<long long> write_count{"write_count"};  // the bin's count after the write

  SC_HAS_PROCESS(TofSpadSensor);
  // `traced`: pixels whose TDC groups and avalanches the trace shows (empty: none; no cost).
  TofSpadSensor(sc_core::sc_module_name name, const TofSpadKernel& kernel, const PixelSelection& sel, RateSource rates,
                long long frames, const std::vector<TracePixel>& traced = {});

  const std::vector<FrameResult>& frames() const { return frames_; }
  const std::vector<std::uint32_t>& words() const { return words_; }  // streamed words of simulated pixels
  bool done() const { return done_; }
  sc_core::sc_time clock_period() const { return period_; }
  const std::vector<std::unique_ptr<GroupProbe>>& group_probes() const { return group_probes_; }
  const std::vector<std::unique_ptr<PixelProbe>>& pixel_probes() const { return pixel_probes_; }
  long long traced_groups_drawn_at_once() const { return drawn_at_once_; }

 private:
  struct TracedHit {
    std::size_t probe;  // index in group_probes_
    int column;
    TdcHit hit;
  };
  void sequencer();
  // One row's integration: one wait, or with traced hits a wait to each hit and its pulses.
  void integrate(int row, long long starts, std::vector<TracedHit> hits);
  void show_hit(int row, const TracedHit& h);
  void clear_pulses();
  int probe_of(int group) const;  // index in group_probes_ of a traced TDC group, or -1

  const TofSpadKernel& kernel_;  // the cycle kernel (owned by the caller)
  PixelSelection sel_;           // simulated pixels
  RateSource rates_;             // scene -> pixel rates
  long long frames_to_run_;      // frames to simulate
  sc_core::sc_time period_;      // one TDC clock cycle (LSB rounded to the time resolution)
  std::vector<FrameResult> frames_;
  std::vector<std::uint32_t> words_;
  bool done_ = false;
  std::vector<std::unique_ptr<GroupProbe>> group_probes_;  // traced TDC groups
  std::vector<std::unique_ptr<PixelProbe>> pixel_probes_;  // traced pixels
  std::vector<std::vector<long long>> write_counts_;       // [probe][column in group x codes + code], this row
  long long drawn_at_once_ = 0;                            // traced groups the aggregated/sparse path drew
};

// Elaborates the module with signals, runs it (bounded by the expected time plus a margin) and
// returns the frames; `sc_errors` receives the SC_ERROR count. One elaboration per process.
struct SystemcRun {
  std::vector<FrameResult> frames;
  std::vector<std::uint32_t> words;
  long long sc_errors = 0;
  double simulated_time_s = 0;  // sc_time_stamp at the end, in s of the modelled clock (cycles x LSB)
  long long measured_cycles = 0;
  long long traced_groups_drawn_at_once = 0;  // traced TDC groups without hits in the trace (aggregated/sparse)
};
SystemcRun run_tof_spad_systemc(const TofSpadKernel& kernel, const PixelSelection& sel, const RateSource& rates,
                                long long frames, const std::string& vcd_base = "",
                                const std::vector<TracePixel>& traced = {});

// Bare-kernel counterpart: frames and the word stream the module would emit. `progress` (may be
// empty) is called after each frame with the frames done; it may throw to stop the run.
SystemcRun run_tof_spad_kernel(const TofSpadKernel& kernel, const PixelSelection& sel, const RateSource& rates,
                               long long frames, const std::function<void(long long)>& progress = {});

}  // namespace rangesim::systemc::spad
