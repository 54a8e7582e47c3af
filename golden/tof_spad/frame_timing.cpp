// Placeholder until the clock schedule of tof-spad lands.
#include <stdexcept>

#include "golden/evaluate_sensor.h"

namespace rangesim::golden {

FrameTiming frame_timing_tof_spad(const ParamSet&) { throw std::logic_error("no clock schedule yet"); }

}  // namespace rangesim::golden
