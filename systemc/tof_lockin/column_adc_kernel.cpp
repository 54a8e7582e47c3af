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
      top_(static_cast<double>((1LL << cfg.readout.adc_bits) - 1)),
      codes_(1LL << cfg.readout.adc_bits),
      conv_(cfg.readout.adc_conversion_cycles) {}

}  // namespace rangesim::systemc::lockin
