#pragma once
// Cycle kernel of the ls-conventional readout sequencer: the controller of one frame access
// (one sheet-beam position), all rows in parallel. Plain C++, no SystemC.
//
// Schedule of a frame access (cycle c = 0 .. F-1 within it; R, L, S, B, O from FrameTimingConfig,
// N samplings, P = L + S + A B with A = addresses_per_sampling):
//   c in [0, R)                      reset     pix_reset: photodiodes reset, centre processors cleared
//   sampling k = 1..N, base = R + (k-1) P:
//     c in [base, base + L)          latch     comparators latched at t_k (pixel array), sampling = k;
//                                              search_start in the last latch cycle (the address
//                                              search latches the activation row at its end)
//     c in [base + L, base + L + S)  search    chained search settles
//     c in [base + L + S, base + P)  address_stream   A B address bits, MSB first, per row
//   c in [R + N P, F)                output    centres out of the row-parallel processors;
//                                              frame_done in the last cycle
// F = R + N P + O = golden::frame_timing(...).frame_cycles. Frame accesses follow back to back.
//
// Two ways to advance: tick() (one clock edge) or advance_to(cycle) (event skipping: jump to a
// later cycle in O(1); the pins are constant between next_event_cycle()s).
#include <array>
#include <cstdint>
#include <vector>

#include "core/ls_conventional/config.h"

namespace rangesim::systemc {

enum class ReadoutPhase : int { Reset = 0, Latch = 1, Search = 2, AddressStream = 3, Output = 4 };
inline constexpr int kReadoutPhases = 5;
// Names as golden::frame_timing's phases.
const char* readout_phase_name(ReadoutPhase p);

// Output ports of the sequencer during one cycle.
struct MultisamplingSequencerPins {
  ReadoutPhase phase = ReadoutPhase::Reset;
  bool pix_reset = false;     // reset phase
  bool latch = false;         // latch phase (comparator latch)
  bool search_start = false;  // last latch cycle: start strobe of every row's address search
  bool frame_done = false;    // last cycle of the frame access
  int sampling = 0;           // k (1..N) during latch/search/stream of sampling k, else 0
  std::uint64_t frame = 0;    // frame-access counter
  bool operator==(const MultisamplingSequencerPins& o) const {
    return phase == o.phase && pix_reset == o.pix_reset && latch == o.latch && search_start == o.search_start &&
           frame_done == o.frame_done && sampling == o.sampling && frame == o.frame;
  }
};

class MultisamplingSequencerKernel {
 public:
  // Throws std::invalid_argument naming the field for a schedule that cannot run.
  MultisamplingSequencerKernel(const FrameTimingConfig& timing, int samplings);

  // One rising clock edge; synchronous reset back to cycle 0 of frame 0 (which is held while rst).
  void tick(bool rst);
  const MultisamplingSequencerPins& pins() const { return pins_; }  // of the current cycle (cached)
  MultisamplingSequencerPins pins_at(long long cycle) const;

  long long cycle() const { return cycle_; }  // cycles since reset release
  long long cycle_in_frame() const { return cycle_ % frame_cycles_; }
  long long frame_cycles() const { return frame_cycles_; }  // F
  // First cycle after the current one at which any pin changes.
  long long next_event_cycle() const;
  // Jumps to `cycle` (>= cycle()) as if ticked (cycle - cycle()) times without reset.
  void advance_to(long long cycle);

  const FrameTimingConfig& timing() const { return timing_; }
  int samplings() const { return samplings_; }

 private:
  FrameTimingConfig timing_;         // R, L, S, B, A, O
  int samplings_;                    // N
  long long period_ = 0;             // P = L + S + A B, one sampling
  long long frame_cycles_ = 0;       // F
  std::vector<long long> events_;    // cycles within a frame at which pins change (sorted, ends with F)
  std::vector<MultisamplingSequencerPins> event_pins_;  // pins_at(events_[i]) in frame 0, but the last
  long long cycle_ = 0;              // current cycle since reset release
  MultisamplingSequencerPins pins_;  // pins_at(cycle_), recomputed only when the cycle moves
  // Event skipping's cursor, valid after an advance_to (tick leaves it): the current frame access
  // (its number and first cycle) and the index in events_ of the first event after cycle_. An
  // advance to that event then takes its pins from event_pins_, without pins_at's divisions.
  bool cursor_ = false;
  std::uint64_t frame_ = 0;
  long long frame_start_ = 0;
  std::size_t next_ = 0;
  void seek();  // the cursor from cycle_
};

}  // namespace rangesim::systemc
