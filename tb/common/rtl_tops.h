#pragma once
// The RTL tops a sensor's preset can be verilated as, and the Verilog parameters each takes from
// it: the one way parameters reach the RTL, preset -> config (core/<sensor>/config.h) ->
// Verilog parameters (tb/<sensor>/verilog_parameters.h). Two users: the build verilates every
// built-in instance (rtl/<sensor>/instances.cmake) with the parameters of its instance preset
// (rtl/<sensor>/instances/*.toml) through rangesim-rtl-parameters (tb/common/rtl_parameters_main.cpp);
// `rangesim cosim <preset.toml>` verilates a user's preset at run time (tb/common/rtl_build.h).
#include <string>
#include <vector>

#include "core/params.h"
#include "tb/common/verilog_parameters.h"

namespace rangesim::tb {

struct RtlTop {
  const char* top;                                          // module: rtl/<sensor>/<top>.sv or rtl/common/<top>.sv
  VerilogParameters (*parameters)(const ParamSet& preset);  // UserError when the RTL cannot take the preset
};

// Each sensor lists its tops in tb/<sensor>/verilog_parameters.cpp (<sensor>_rtl_tops()).
// UserError naming the preset when its sensor has no top of that name.
VerilogParameters rtl_top_parameters(const ParamSet& preset, const std::string& top);

}  // namespace rangesim::tb
