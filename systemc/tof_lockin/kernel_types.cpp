#include "systemc/tof_lockin/kernel_types.h"

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

const char* phase_name(LockinPhase p) {
  switch (p) {
    case LockinPhase::Phase1: return "phase1";
    case LockinPhase::Phase2: return "phase2";
    case LockinPhase::Phase3: return "phase3";
    case LockinPhase::AdcConversion: return "adc_conversion";
    case LockinPhase::Output: return "output";
    case LockinPhase::Idle: return "idle";
  }
  return "?";
}

}  // namespace rangesim::systemc::lockin
