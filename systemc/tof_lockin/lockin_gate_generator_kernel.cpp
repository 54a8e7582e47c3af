#include "systemc/tof_lockin/lockin_gate_generator_kernel.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <fmt/format.h>
#include <limits>
#include <random>

#include "core/physics.h"
#include "core/user_error.h"
#include "golden/tof_lockin/pulse_timing.h"
#include "golden/tof_lockin/tap_charge.h"
#include "systemc/common/poisson_sampler.h"
#include "systemc/common/random_stream.h"

namespace rangesim::systemc::lockin {

// ---------------------------------------------------------------- gate timing
// generator

LockinGateGeneratorKernel::LockinGateGeneratorKernel(const TofLockinConfig& cfg) {
  const double fg = cfg.gates.clock_Hz;
  const double t0 = cfg.source.pulse_width_s * fg;
  const double period = cfg.source.pulse_width_s / cfg.source.duty_cycle * fg;
  t0_ = gate_t0_cycles(cfg);
  period_ = gate_period_cycles(cfg);
  n_acc_ = cfg.gates.accumulations_per_frame;
  if (t0_ < 1 || std::fabs(t0 - static_cast<double>(t0_)) > 1e-6 * std::max(1.0, t0))
    throw UserError(
        fmt::format("source.pulse_width_s = {:g} is {:g} cycles of "
                    "gates.clock_Hz = {:g}; allowed: a whole "
                    "number >= 1 of gate-clock cycles",
                    cfg.source.pulse_width_s, t0, fg));
  if (period_ < 2 * t0_ || std::fabs(period - static_cast<double>(period_)) > 1e-6 * std::max(1.0, period))
    throw UserError(
        fmt::format("source.pulse_width_s / source.duty_cycle = {:g} s is {:g} cycles of "
                    "gates.clock_Hz = "
                    "{:g}; allowed for the clock-level model: a whole number of gate-clock "
                    "cycles >= 2 T0",
                    cfg.source.pulse_width_s / cfg.source.duty_cycle, period, fg));
  acc_ = n_acc_;  // idle until start()
}

void LockinGateGeneratorKernel::start() { acc_ = 0, cyc_ = 0; }

LockinPhase LockinGateGeneratorKernel::phase() const {
  if (done()) return LockinPhase::Idle;
  return cyc_ < t0_ ? LockinPhase::Phase1 : cyc_ < 2 * t0_ ? LockinPhase::Phase2 : LockinPhase::Phase3;
}

long long LockinGateGeneratorKernel::cycles_to_edge() const {
  if (done()) return 0;
  return cyc_ < t0_ ? t0_ - cyc_ : cyc_ < 2 * t0_ ? 2 * t0_ - cyc_ : period_ - cyc_;
}

bool LockinGateGeneratorKernel::advance(long long n) {
  assert(n >= 1 && n <= cycles_to_edge());
  cyc_ += n;
  const bool closed = cyc_ == t0_ || cyc_ == 2 * t0_ || cyc_ == period_;
  if (cyc_ == period_) cyc_ = 0, ++acc_;
  return closed;
}

long long LockinGateGeneratorKernel::finish_all() {
  const long long skipped = (n_acc_ - acc_) * period_ - cyc_;
  acc_ = n_acc_, cyc_ = 0;
  return skipped;
}

}  // namespace rangesim::systemc::lockin
