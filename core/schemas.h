#pragma once
// Parameter schemas of the four sensor presets: every key, its unit, range and meaning.
#include "core/params.h"

namespace rangesim {

const ParamSchema& ls_conventional_schema();
const ParamSchema& ls_demodulation_schema();
const ParamSchema& tof_lockin_schema();
const ParamSchema& tof_spad_schema();

}  // namespace rangesim
