#pragma once
// Clock-level SystemC model of the ls-conventional sensor (thesis [31]): the top-level sc_module
// that connects the block modules exactly as LsConventionalSensorKernel connects their kernels:
//
//   MultisamplingSequencer --pix_reset/sampling/frame--> PixelArray --act[r]--> RowReadoutArray:
//          |--search_start------------------------------------------->  AddressSearch[r]
//          |--pix_reset (clear)---------------------------------------> -> CentreProcessor[r]
//
// The rows' searches and centre processors are one module with one clocked process and one
// vector-payload output (systemc/ls_conventional/row_readout_array.h) rather than 2 x 365 modules with per-row
// signals: the same kernels at a fraction of the scheduler's and the elaboration's cost.
//
// The module counts cycles by phase, collects one FrameResult per frame access at frame_done
// (the centre processors' outputs during the last cycle), checks the schedule (no search start
// while a row is busy, every search idle at the end of the frame; SC_REPORT_ERROR otherwise) and
// can stop the simulation after a number of frame accesses.
#include <functional>
#include <string>
#include <memory>
#include <systemc>

#include "systemc/common/simulate_entry.h"
#include "systemc/common/waveform.h"
#include <vector>

#include "core/ls_conventional/config.h"
#include "systemc/common/address_search.h"
#include "systemc/ls_conventional/sensor_kernel.h"
#include "systemc/ls_conventional/pixel_array.h"
#include "systemc/ls_conventional/multisampling_sequencer.h"
#include "systemc/ls_conventional/row_readout_array.h"

namespace rangesim::systemc {

class LsConventionalSensor : public sc_core::sc_module {
 public:
  sc_core::sc_in<bool> clk_i{"clk_i"};  // rising edge active
  sc_core::sc_in<bool> rst_i{"rst_i"};  // synchronous, active high

  SC_HAS_PROCESS(LsConventionalSensor);
  // Throws std::invalid_argument for an unbuildable configuration (from the kernels).
  LsConventionalSensor(sc_core::sc_module_name name, const LsConventionalConfig& config,
                       const PixelArrayOptions& options, StimulusSource source);

  // Calls sc_stop() after this many frame results (0: never).
  void stop_after(long long frames) { stop_after_ = frames; }
  // Called after each frame result with the number of results so far.
  void on_frame(std::function<void(long long)> callback) { on_frame_ = std::move(callback); }
  // Adds the sequencer's pins and, for each of `rows`, the search and centre pins to `tf`.
  // Must be called before sc_start (plain SystemC signals, no Verilated model here).
  // The sequencer and, for each of `rows`, its address search and centre processor, in the
  // scopes ls_conventional.sequencer and ls_conventional.row<r>.<block>.
  // `pixels`: the comparator output of each, as latched into its row's activation at every edge,
  // in ls_conventional.pixel_<r>_<c>.active (kept only for these pixels).
  void trace(Waveform& w, const std::vector<int>& rows, const std::vector<TracePixel>& pixels = {});

  const std::vector<FrameResult>& results() const { return results_; }
  long long cycles() const { return cycle_; }                            // since reset release
  sc_core::sc_time reset_release_time() const { return release_time_; }  // time of the last reset edge
  const PixelArray& pixel_array() const { return pixels_; }

 private:
  void on_clock();  // phase accounting, checks and result collection

  LsConventionalConfig config_;
  // Block modules.
  MultisamplingSequencer sequencer_;
  PixelArray pixels_;
  RowReadoutArray rows_;  // every row's address search and centre processor
  // Sequencer outputs.
  sc_core::sc_signal<bool> pix_reset_{"pix_reset"}, latch_{"latch"}, search_start_{"search_start"},
      frame_done_{"frame_done"};
  sc_core::sc_signal<unsigned> phase_{"phase"}, sampling_{"sampling"};
  sc_core::sc_signal<sc_dt::uint64> frame_{"frame"};
  // Per row.
  sc_core::sc_vector<sc_core::sc_signal<ActivationRow>> act_{"act"};
  sc_core::sc_signal<RowArrayPins> row_pins_{"row_pins"};  // every row's search and centre pins
  // Bookkeeping.
  std::array<long long, kReadoutPhases> phase_cycles_{};  // of the current frame
  std::vector<FrameResult> results_;
  long long cycle_ = 0;  // cycles since reset release
  long long stop_after_ = 0;
  std::function<void(long long)> on_frame_;
  sc_core::sc_time release_time_;
  struct PixelProbe {
    TracePixel at;
    std::unique_ptr<bool> active;  // traced by reference: fixed storage
  };
  std::vector<PixelProbe> pixel_probes_;  // traced pixels (updated at every edge)
};

// ---- Running the sensor: bare kernel or SystemC, same options, same results ----

struct SensorRunOptions {
  long long frames = 1;                     // frame accesses to simulate
  long long cycle_budget = 0;               // bound on simulated cycles (0: 2 frame accesses per frame + 16)
  std::string vcd_base;                     // SystemC only: "" = no trace, else writes <vcd_base>.vcd
  std::vector<int> traced_rows;             // rows whose search and centre pins are traced
  std::vector<TracePixel> traced_pixels;    // pixels whose comparator output is traced
  std::function<void(long long)> progress;  // after each frame access (frames done so far)
  int threads = 1;  // bare kernel: this many threads, each with a part of the run (same results)
  // How the bare kernel's threads share the run: consecutive frame accesses each (Auto, when there
  // are at least as many as threads: nothing is done twice), or bands of rows (every thread makes
  // every frame access's schedule and row shapes for its rows).
  enum class Split { Auto, FrameAccesses, RowBands };
  Split split = Split::Auto;
};

struct SensorRunResult {
  std::vector<FrameResult> frames;  // one per frame access
  long long cycles = 0;             // simulated cycles since reset release
  double simulated_time_s = 0;      // SystemC: sc_time_stamp() - reset release; kernel: cycles / clock
  double wall_time_s = 0;           // host time of the run (elaboration included for SystemC)
  long long sc_errors = 0;          // SC_ERROR reports (SystemC)
  long long sc_warnings = 0;        // SC_WARNING reports (SystemC)
  std::vector<std::string> errors;  // kernel protocol violations
  long long pixels_simulated = 0;   // pixels simulated one by one (sparse windows)
  long long ticks = 0;              // clock edges evaluated (kernel; SystemC: = cycles)
  // Bare kernel: CPU time of each part's thread (CLOCK_THREAD_CPUTIME_ID); [0] is the calling
  // thread, which also sets up, runs part 0 and merges. Their maximum is the run's critical path.
  std::vector<double> thread_cpu_s;
};

// Bare kernel, on run.threads threads (run.split; the keyed streams make the result the same for
// any thread count and split). Throws std::runtime_error if the cycle budget runs out.
SensorRunResult run_sensor_kernel(const LsConventionalConfig& config, const SensorKernelOptions& options,
                                  StimulusSource source, const SensorRunOptions& run);

// Under SystemC: clock at timing.clock_Hz (1 fs resolution), reset for 2 edges, then frames.
// Elaborates, so at most once per process, and it must be the process's first SystemC use
// (it sets the time resolution). Throws std::runtime_error if the budget runs out; SC_ERRORs
// thrown by processes come out as sc_core::sc_report.
SensorRunResult run_sensor_systemc(const LsConventionalConfig& config, const SensorKernelOptions& options,
                                   StimulusSource source, const SensorRunOptions& run);

}  // namespace rangesim::systemc
