// Placeholder until the clock schedule of tof-lockin lands.
#include <stdexcept>

#include "golden/evaluate_sensor.h"

namespace rangesim::golden {

FrameTiming frame_timing_tof_lockin(const ParamSet&) { throw std::logic_error("no clock schedule yet"); }

}  // namespace rangesim::golden
