#pragma once
// The one map from an ls-conventional config to the Verilog parameters of
// rtl/ls_conventional/ls_conventional_readout.sv. Used for the instances verilated at run time
// (`rangesim cosim <preset.toml>`) and to check that the built-in instances of rtl/CMakeLists.txt
// were verilated with the configs their harness runs (tb/ls_conventional/cosim.cpp).
#include <string>

#include "core/ls_conventional/config.h"
#include "tb/common/verilog_parameters.h"

namespace rangesim::tb {

// ROWS, COLUMNS, ADDRESS_BITS, SAMPLINGS, RESET_CYCLES, LATCH_CYCLES, SEARCH_CYCLES,
// OUTPUT_CYCLES. UserError naming `origin` and the key when the RTL cannot take the config (it
// streams the left and right edge, from 1-bit comparators).
VerilogParameters verilog_parameters(const LsConventionalConfig& cfg, const std::string& origin);

}  // namespace rangesim::tb
