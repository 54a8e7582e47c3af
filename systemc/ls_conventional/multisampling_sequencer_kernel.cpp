#include "systemc/ls_conventional/multisampling_sequencer_kernel.h"

#include <algorithm>
#include <cassert>
#include <stdexcept>
#include <string>

namespace rangesim::systemc {

const char* readout_phase_name(ReadoutPhase p) {
  switch (p) {
    case ReadoutPhase::Reset: return "reset";
    case ReadoutPhase::Latch: return "latch";
    case ReadoutPhase::Search: return "search";
    case ReadoutPhase::AddressStream: return "address_stream";
    case ReadoutPhase::Output: return "output";
  }
  return "?";
}

namespace {
void require(bool ok, const std::string& what) {
  if (!ok) throw std::invalid_argument("MultisamplingSequencerKernel: " + what);
}
}  // namespace

MultisamplingSequencerKernel::MultisamplingSequencerKernel(const FrameTimingConfig& timing, int samplings)
    : timing_(timing), samplings_(samplings) {
  require(samplings >= 1, "samplings must be >= 1, got " + std::to_string(samplings));
  require(timing.reset_cycles >= 1, "reset_cycles must be >= 1, got " + std::to_string(timing.reset_cycles));
  require(timing.latch_cycles >= 1, "latch_cycles must be >= 1, got " + std::to_string(timing.latch_cycles));
  require(timing.search_cycles >= 1, "search_cycles must be >= 1, got " + std::to_string(timing.search_cycles));
  require(timing.address_bits >= 1, "address_bits must be >= 1, got " + std::to_string(timing.address_bits));
  require(timing.addresses_per_sampling >= 1,
          "addresses_per_sampling must be >= 1, got " + std::to_string(timing.addresses_per_sampling));
  require(timing.output_cycles >= 1, "output_cycles must be >= 1, got " + std::to_string(timing.output_cycles));
  period_ = sampling_cycles(timing);
  frame_cycles_ = ::rangesim::frame_cycles(timing, samplings);
  // Pin changes within a frame: phase starts, the search_start cycle and the frame_done cycle.
  const long long R = timing.reset_cycles, L = timing.latch_cycles, S = timing.search_cycles;
  events_.push_back(0);
  for (int k = 0; k < samplings; ++k) {
    const long long base = R + k * period_;
    for (long long e : {base, base + L - 1, base + L, base + L + S}) events_.push_back(e);
  }
  events_.push_back(R + samplings * period_);
  events_.push_back(frame_cycles_ - 1);
  events_.push_back(frame_cycles_);
  std::sort(events_.begin(), events_.end());
  events_.erase(std::unique(events_.begin(), events_.end()), events_.end());
  for (std::size_t i = 0; i + 1 < events_.size(); ++i) event_pins_.push_back(pins_at(events_[i]));
  pins_ = pins_at(0);
}

void MultisamplingSequencerKernel::tick(bool rst) {
  cycle_ = rst ? 0 : cycle_ + 1;
  pins_ = pins_at(cycle_);
  cursor_ = false;
}

MultisamplingSequencerPins MultisamplingSequencerKernel::pins_at(long long cycle) const {
  MultisamplingSequencerPins p;
  p.frame = static_cast<std::uint64_t>(cycle / frame_cycles_);
  const long long c = cycle % frame_cycles_;
  const long long R = timing_.reset_cycles, L = timing_.latch_cycles, S = timing_.search_cycles;
  if (c < R) {
    p.phase = ReadoutPhase::Reset;
    p.pix_reset = true;
  } else if (c < R + samplings_ * period_) {
    const long long j = (c - R) % period_;
    p.sampling = static_cast<int>((c - R) / period_) + 1;
    if (j < L) {
      p.phase = ReadoutPhase::Latch;
      p.latch = true;
      p.search_start = j == L - 1;
    } else if (j < L + S) {
      p.phase = ReadoutPhase::Search;
    } else {
      p.phase = ReadoutPhase::AddressStream;
    }
  } else {
    p.phase = ReadoutPhase::Output;
  }
  p.frame_done = c == frame_cycles_ - 1;
  return p;
}

long long MultisamplingSequencerKernel::next_event_cycle() const {
  if (cursor_) return frame_start_ + events_[next_];
  const long long c = cycle_in_frame();
  const auto it = std::upper_bound(events_.begin(), events_.end(), c);
  assert(it != events_.end());
  return cycle_ - c + *it;
}

void MultisamplingSequencerKernel::seek() {
  const long long c = cycle_in_frame();
  frame_ = static_cast<std::uint64_t>(cycle_ / frame_cycles_);
  frame_start_ = cycle_ - c;
  next_ = static_cast<std::size_t>(std::upper_bound(events_.begin(), events_.end(), c) - events_.begin());
  cursor_ = true;
}

void MultisamplingSequencerKernel::advance_to(long long cycle) {
  assert(cycle >= cycle_ && "advance_to goes forward only");
  if (cursor_ && cycle == frame_start_ + events_[next_]) {  // the next event, as event skipping goes
    cycle_ = cycle;
    if (next_ + 1 == events_.size()) {  // F: the next frame access's first cycle
      ++frame_;
      frame_start_ = cycle;
      next_ = 0;
    }
    pins_ = event_pins_[next_++];
    pins_.frame = frame_;
    return;
  }
  cycle_ = cycle;
  pins_ = pins_at(cycle_);
  seek();
}

}  // namespace rangesim::systemc
