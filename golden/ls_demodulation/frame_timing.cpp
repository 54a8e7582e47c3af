// Placeholder until the clock schedule of ls-demodulation lands.
#include <stdexcept>

#include "golden/evaluate_sensor.h"

namespace rangesim::golden {

FrameTiming frame_timing_ls_demodulation(const ParamSet&) { throw std::logic_error("no clock schedule yet"); }

}  // namespace rangesim::golden
