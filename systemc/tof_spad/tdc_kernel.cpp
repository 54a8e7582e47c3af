#include "systemc/tof_spad/tdc_kernel.h"

#include <algorithm>
#include <cassert>

#include "systemc/tof_spad/sensor_kernel.h"

namespace rangesim::systemc::spad {

TdcGroupKernel::TdcGroupKernel(int phase_bins, int codes, int block_event_bins, int block_overflow_bins,
                               long long laser_cycles, int columns)
    : np_(phase_bins),
      nc_(codes),
      block_event_(block_event_bins),
      block_overflow_(block_overflow_bins),
      laser_cycles_(laser_cycles),
      events_(static_cast<size_t>(columns), std::vector<long long>(static_cast<size_t>(codes), 0)),
      armed_diff_(static_cast<size_t>(phase_bins) + 1, 0) {}

// Armed at the start of absolute bins [from, to]: partial first/last cycles into the
// difference array, whole cycles into a counter.
void TdcGroupKernel::add_armed(long long from, long long to) {
  if (from > to) return;
  const long long kf = from / np_, kt = to / np_;
  const int pf = static_cast<int>(from % np_), pt = static_cast<int>(to % np_);
  if (kf == kt) {
    ++armed_diff_[static_cast<size_t>(pf)], --armed_diff_[static_cast<size_t>(pt) + 1];
    return;
  }
  ++armed_diff_[static_cast<size_t>(pf)], --armed_diff_[static_cast<size_t>(np_)];
  full_cycles_ += kt - kf - 1;
  ++armed_diff_[0], --armed_diff_[static_cast<size_t>(pt) + 1];
}

void TdcGroupKernel::lose() { ++lost_; }

TdcHit TdcGroupKernel::hit(int who, long long cycle, int bin) {
  assert(cycle >= 0 && cycle < laser_cycles_ && bin >= 0 && bin < np_);
  TdcHit h;
  h.abs_bin = cycle * np_ + bin;
  h.code = bin;
  if (h.abs_bin < armed_from_) {
    ++lost_;
    return h;
  }
  add_armed(armed_from_, h.abs_bin);
  long long rearm;
  if (bin < nc_) {
    ++events_[static_cast<size_t>(who)][static_cast<size_t>(bin)];
    rearm = h.abs_bin + block_event_;
    h.kind = TdcHit::Kind::Event;
  } else {
    ++overflows_;
    rearm = h.abs_bin + block_overflow_;
    h.kind = TdcHit::Kind::Overflow;
  }
  armed_from_ = std::max(rearm, (cycle + 1) * np_);  // a stopped TDC waits for the next START
  return h;
}

GroupHistogram TdcGroupKernel::finish() {
  add_armed(armed_from_, laser_cycles_ * np_ - 1);
  armed_from_ = laser_cycles_ * np_;  // nothing more is armed
  GroupHistogram g;
  g.events = events_;
  g.armed.assign(static_cast<size_t>(nc_), 0);
  long long run = 0;
  for (int i = 0; i < nc_; ++i)
    run += armed_diff_[static_cast<size_t>(i)], g.armed[static_cast<size_t>(i)] = run + full_cycles_;
  g.starts = laser_cycles_;
  g.overflows = overflows_;
  g.lost_busy = lost_;
  return g;
}

}  // namespace rangesim::systemc::spad
