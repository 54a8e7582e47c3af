#pragma once
// The TDC shared by one group of tof-spad columns, one hit at a time: first-hit arbitration has
// already picked the hit (the caller presents the group's avalanches in time order), this
// decides lost / event / overflow, keeps the dead time (block bins) and the stop-until-START
// rule, and accumulates the histogram and the armed counts. TofSpadKernel::simulate_group runs
// it on the event-driven avalanches; the co-simulation (tb/tof_spad/cosim.cpp) uses it as the
// per-hit reference of rtl/tof_spad/tdc.sv, whose clock cycle is one absolute bin.
#include <cstdint>
#include <vector>

namespace rangesim::systemc::spad {

struct GroupHistogram;

struct TdcHit {
  enum class Kind { Lost, Event, Overflow } kind = Kind::Lost;
  long long abs_bin = 0;  // cycle x Np + bin: bins since the row's first START
  int code = 0;           // the hit's TDC code (bin)
};

class TdcGroupKernel {
 public:
  // Np phase bins per laser period, Nc codes with events, dead times in bins, L laser cycles.
  TdcGroupKernel(int phase_bins, int codes, int block_event_bins, int block_overflow_bins, long long laser_cycles,
                 int columns);
  // Hit of column `who` in laser cycle `cycle` (< L) falling in TDC code `bin` (0 .. Np-1).
  TdcHit hit(int who, long long cycle, int bin);
  // An avalanche that cannot be timed (before the first START): counted as lost.
  void lose();
  // After the last hit: the armed counts of the whole integration; returns the histogram
  // (events, armed, starts, overflows, lost_busy; the caller adds avalanches / photons).
  GroupHistogram finish();
  long long armed_from() const { return armed_from_; }

 private:
  void add_armed(long long from, long long to);

  int np_, nc_, block_event_, block_overflow_;
  long long laser_cycles_;
  std::vector<std::vector<long long>> events_;  // [column][code]
  std::vector<long long> armed_diff_;           // difference array of armed bins per phase bin
  long long full_cycles_ = 0;                   // whole laser cycles armed throughout
  long long armed_from_ = 0;                    // absolute bin from which the TDC is armed
  long long overflows_ = 0, lost_ = 0;
};

}  // namespace rangesim::systemc::spad
