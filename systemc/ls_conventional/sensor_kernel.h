#pragma once
// The clock-level ls-conventional sensor as one plain C++ kernel: the readout sequencer, the pixel
// array with its comparators, one address search and one centre processor per row, connected
// exactly as the sc_modules are in systemc/ls_conventional/sensor.h (same kernels, same order of
// evaluation), so the bare kernel and the SystemC model give identical outputs cycle for cycle.
//
// Per clock edge (tick()): every block reads its inputs as they were during the ending cycle,
// then all update; afterwards the pixel array reacts combinationally to the sequencer's new pins
// (reset for a new frame access, comparator latch for a new sampling).
//
// Event skipping (step() with SensorKernelOptions::event_skipping): the sequencer jumps from one
// pin change to the next (readout_sequencer_kernel.h); at a search start each row's search is
// evaluated in closed form (AddressSearchKernel::evaluate) and handed to its centre processor
// whole (CentreProcessorKernel::accumulate). Idle and streaming cycles are counted, not ticked.
// tests/systemc proves both paths give identical frame results and phase cycle counts.
#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "core/ls_conventional/config.h"
#include "systemc/common/address_search_kernel.h"
#include "systemc/ls_conventional/centre_processor_kernel.h"
#include "systemc/ls_conventional/frame_stimulus.h"
#include "systemc/ls_conventional/pixel_array_kernel.h"
#include "systemc/ls_conventional/multisampling_sequencer_kernel.h"

namespace rangesim::systemc {

struct SensorKernelOptions {
  PixelArrayOptions pixel;     // noise, seed, sparse, the band of rows
  bool event_skipping = true;  // step() jumps to the next event instead of ticking every cycle
  // FrameResult::extents filled. A Monte Carlo trial tells an outlier by them; a range map reads
  // only the pins (simulate turns them off: a third of the results' bytes, 7% of the plane map).
  bool frame_extents = true;
};

// Outcome of one frame access.
struct FrameResult {
  std::uint64_t frame = 0;                // frame-access counter (beam position index in a range map)
  std::vector<CentreProcessorPins> rows;  // centre per row (of the kernel's band), as output in the frame's last cycle
  // Per row (of the band), the extent of the activations latched by the last sampling (activations
  // only grow, so it holds every pixel that fired in the frame): a Monte Carlo trial tells an outlier
  // by it. The kernel's view of its pixel array, not an output pin: the sc_module and the RTL do not
  // fill it, nor the kernel with SensorKernelOptions::frame_extents off, and == leaves it out.
  std::vector<ActivationExtent> extents;
  long long end_cycle = 0;                               // cycles since reset release at the end of this frame
  long long cycles = 0;                                  // cycles of this frame access
  std::array<long long, kReadoutPhases> phase_cycles{};  // by ReadoutPhase
  int rows_detected() const;
  bool operator==(const FrameResult& o) const {
    return frame == o.frame && rows == o.rows && end_cycle == o.end_cycle && cycles == o.cycles &&
           phase_cycles == o.phase_cycles;
  }
};

class LsConventionalSensorKernel {
 public:
  // Throws std::invalid_argument for an unbuildable configuration (from the block kernels), or if
  // the search and timing configs disagree on address_bits / addresses_per_sampling.
  LsConventionalSensorKernel(const LsConventionalConfig& config, const SensorKernelOptions& options,
                             StimulusSource source);

  void reset();  // synchronous reset edge (held 1 edge), then the pixel array settles
  // reset(), then on to the first cycle of frame access `frame` as if the ones before it had run.
  // Every frame access starts from the same state (pixels and centre processors reset, searches
  // idle) and its noise is keyed by its number, so its result does not depend on them: a thread
  // can simulate a later part of a run (run_sensor_kernel).
  void reset_at_frame(std::uint64_t frame);
  void tick();  // one clock edge of every block
  void step();  // tick(), or with event skipping a jump to the next pin change of the sequencer

  // Runs until `frames` more frame results exist; throws std::runtime_error if that takes more
  // than `cycle_budget` cycles (0: 2 frame accesses' worth per frame). Returns the new results.
  std::vector<FrameResult> run_frames(long long frames, long long cycle_budget = 0);
  // The same without returning them (results() holds them): no copy per call.
  void advance_frames(long long frames, long long cycle_budget = 0);

  const std::vector<FrameResult>& results() const { return results_; }
  std::vector<FrameResult> take_results() { return std::move(results_); }
  void reserve_results(long long frames) { results_.reserve(static_cast<std::size_t>(frames)); }
  // Forgets the stored results: a caller that takes each frame from run_frames() (Monte Carlo
  // trials, one frame each) keeps memory bounded instead of growing by one result per frame.
  void clear_results() { results_.clear(); }
  const std::vector<std::string>& errors() const { return errors_; }  // protocol violations
  long long cycle() const { return sequencer_.cycle(); }
  long long ticks() const { return ticks_; }  // clock edges actually evaluated (tick mode)

  const MultisamplingSequencerKernel& sequencer() const { return sequencer_; }
  const PixelArrayKernel& pixels() const { return pixels_; }
  // The rows' blocks as ticking leaves them. With event skipping on the exact path a frame access's
  // searches and centres are worked out at its end by extent pattern and these stay idle and clear:
  // the frame's results hold their pins.
  const AddressSearchKernel& search(int row) const { return search_[static_cast<std::size_t>(row)]; }
  const CentreProcessorKernel& centre(int row) const { return centre_[static_cast<std::size_t>(row)]; }
  const LsConventionalConfig& config() const { return config_; }

 private:
  void settle();  // pixel array follows the sequencer's pins
  void account(const MultisamplingSequencerPins& p, long long cycles);
  void finish_frame(const MultisamplingSequencerPins& p);  // in the frame_done cycle
  void prepare_next_result();                              // finish_frame: the next result's memory
  template <class F>
  void for_each_extent(F f) const;  // f(r, extent of row r at the current sampling), every row

  LsConventionalConfig config_;
  SensorKernelOptions options_;
  MultisamplingSequencerKernel sequencer_;
  PixelArrayKernel pixels_;
  std::vector<AddressSearchKernel> search_;               // per row
  std::vector<CentreProcessorKernel> centre_;             // per row
  std::vector<AddressSearchPins> search_pins_;            // scratch: pins of the ending cycle
  std::vector<CentreProcessorPins> pins_scratch_;         // scratch: finish_frame's rows (ticking)
  std::vector<CentreProcessorPins> pattern_pins_;         // scratch: per extent pattern, a row's pins ..
  std::vector<ActivationExtent> pattern_extent_;          // .. and last extent (finish_frame)
  std::vector<CentreProcessorPins> next_rows_;            // the next frame result's rows ..
  std::vector<ActivationExtent> next_extents_;            // .. and extents (prepare_next_result)
  std::array<long long, kReadoutPhases> phase_cycles_{};  // of the current frame
  std::vector<FrameResult> results_;
  // Event skipping on the exact path: the searches' results are worked out at the frame's end,
  // every sampling's at once and once per extent pattern (finish_frame), instead of one pass a
  // sampling; nothing reads the centres in between, and the rows' own processors stay clear.
  bool centres_deferred_ = false;
  bool centres_clear_ = true;  // every row's centre processor is clear (none has taken anything since)
  std::vector<std::string> errors_;
  long long ticks_ = 0;
};

}  // namespace rangesim::systemc
