#pragma once
// The tof-lockin gate timing generator as a plain C++ kernel (rtl/tof_lockin/lockin_gate_generator.sv).
#include "systemc/tof_lockin/kernel_types.h"

namespace rangesim::systemc::lockin {

// ---------------------------------------------------------------- gate timing
// generator
class LockinGateGeneratorKernel {
 public:
  explicit LockinGateGeneratorKernel(const TofLockinConfig& cfg);  // throws UserError if T_rep is off the clock grid
  void start();                                                    // first cycle of PHASE1 of accumulation 0
  bool done() const { return acc_ >= n_acc_; }
  LockinPhase phase() const;
  bool tx1() const { return !done() && cyc_ < t0_; }
  bool tx2() const { return !done() && cyc_ >= t0_ && cyc_ < 2 * t0_; }
  bool txd() const { return !done() && cyc_ >= 2 * t0_; }
  bool light() const { return tx1(); }  // emitted pulse [0, T0) of each period
  long long cycle_in_period() const { return cyc_; }
  long long accumulation() const { return acc_; }
  long long cycles_to_edge() const;  // cycles until the gate pattern changes (>= 1 unless done)
  // Advances n cycles, 1 <= n <= cycles_to_edge(); returns true if a window
  // closed at the end.
  bool advance(long long n);
  // Finishes all remaining periods at once (aggregation); returns the cycles
  // skipped.
  long long finish_all();
  long long t0_cycles() const { return t0_; }
  long long period_cycles() const { return period_; }
  long long accumulations() const { return n_acc_; }
  // Edges of window w (0 = PHASE1, 1 = PHASE2, 2 = PHASE3) in cycles from the
  // period start.
  long long window_open(int w) const { return w == 0 ? 0 : w == 1 ? t0_ : 2 * t0_; }
  long long window_close(int w) const { return w == 0 ? t0_ : w == 1 ? 2 * t0_ : period_; }

 private:
  long long t0_;       // T0 in gate-clock cycles
  long long period_;   // T_rep = T0 / duty in gate-clock cycles
  long long n_acc_;    // accumulations per frame
  long long acc_ = 0;  // current accumulation
  long long cyc_ = 0;  // cycle within the period
};

}  // namespace rangesim::systemc::lockin
