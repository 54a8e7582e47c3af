#include "systemc/tof_lockin/column_adc_kernel.h"

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

// ---------------------------------------------------------------- column ADC

ColumnAdcKernel::ColumnAdcKernel(const TofLockinConfig& cfg)
    : lsb_(cfg.readout.adc_full_scale_V / std::ldexp(1.0, cfg.readout.adc_bits)),
      codes_(1LL << cfg.readout.adc_bits),
      conv_(cfg.readout.adc_conversion_cycles) {}

long long ColumnAdcKernel::code(double v) const {
  return static_cast<long long>(std::clamp(std::floor(v / lsb_), 0.0, static_cast<double>(codes_ - 1)));
}

}  // namespace rangesim::systemc::lockin
