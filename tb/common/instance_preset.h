#pragma once
// The configuration a built-in co-simulation instance runs is the one its RTL was verilated
// from: its instance preset (rtl/<sensor>/instances/*.toml, declared with the instance in
// rtl/<sensor>/instances.cmake and embedded in the build), loaded like any preset.
#include <string>

#include "core/params.h"

namespace rangesim::tb {

// The instance preset of the verilated class `prefix` (e.g. "Vls_conventional_readout_small").
// std::logic_error when the build has no such instance (a programmer error).
ParamSet instance_preset(const std::string& prefix);

}  // namespace rangesim::tb
