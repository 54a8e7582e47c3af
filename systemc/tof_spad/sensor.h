#pragma once
// Thin sc_module around TofSpadKernel: a clocked sequencer thread that, row by row, runs the
// kernel's event-driven integration and waits the integration's cycles (laser STARTs x Np), then
// streams the row's histogram memory out word by word (one word per cycles_per_word clocks).
// Measured cycles come from the simulated time; results must equal the bare kernel's.
#include <cstdint>
#include <functional>
#include <string>
#include <systemc>
#include <vector>

#include "systemc/tof_spad/sensor_kernel.h"

namespace rangesim::systemc::spad {

class TofSpadSensor : public sc_core::sc_module {
 public:
  sc_core::sc_out<int> row_o{"row_o"};                 // row connected to the TDCs
  sc_core::sc_out<int> phase_o{"phase_o"};             // 0 idle, 1 laser cycles, 2 histogram readout
  sc_core::sc_out<bool> word_valid_o{"word_valid_o"};  // a histogram word is on word_o
  sc_core::sc_out<std::uint32_t> word_o{"word_o"};     // histogram word (event count, saturated)

  SC_HAS_PROCESS(TofSpadSensor);
  TofSpadSensor(sc_core::sc_module_name name, const TofSpadKernel& kernel, const PixelSelection& sel, RateSource rates,
                long long frames);

  const std::vector<FrameResult>& frames() const { return frames_; }
  const std::vector<std::uint32_t>& words() const { return words_; }  // streamed words of simulated pixels
  bool done() const { return done_; }
  sc_core::sc_time clock_period() const { return period_; }

 private:
  void sequencer();

  const TofSpadKernel& kernel_;  // the cycle kernel (owned by the caller)
  PixelSelection sel_;           // simulated pixels
  RateSource rates_;             // scene -> pixel rates
  long long frames_to_run_;      // frames to simulate
  sc_core::sc_time period_;      // one TDC clock cycle (LSB rounded to the time resolution)
  std::vector<FrameResult> frames_;
  std::vector<std::uint32_t> words_;
  bool done_ = false;
};

// Elaborates the module with signals, runs it (bounded by the expected time plus a margin) and
// returns the frames; `sc_errors` receives the SC_ERROR count. One elaboration per process.
struct SystemcRun {
  std::vector<FrameResult> frames;
  std::vector<std::uint32_t> words;
  long long sc_errors = 0;
  double simulated_time_s = 0;  // sc_time_stamp at the end, in s of the modelled clock (cycles x LSB)
  long long measured_cycles = 0;
};
SystemcRun run_tof_spad_systemc(const TofSpadKernel& kernel, const PixelSelection& sel, const RateSource& rates,
                                long long frames, const std::string& vcd_base = "");

// Bare-kernel counterpart: frames and the word stream the module would emit. `progress` (may be
// empty) is called after each frame with the frames done; it may throw to stop the run.
SystemcRun run_tof_spad_kernel(const TofSpadKernel& kernel, const PixelSelection& sel, const RateSource& rates,
                               long long frames, const std::function<void(long long)>& progress = {});

}  // namespace rangesim::systemc::spad
