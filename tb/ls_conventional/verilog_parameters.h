#pragma once
// The one map from an ls-conventional config to the Verilog parameters of
// rtl/ls_conventional/ls_conventional_readout.sv and, through ls_conventional_rtl_tops()
// (tb/common/rtl_tops.h), of its blocks. Used for the built-in instances (at build time, from
// rtl/ls_conventional/instances/) and for a preset's own (`rangesim cosim <preset.toml>`).
#include <string>

#include "core/ls_conventional/config.h"
#include "tb/common/verilog_parameters.h"

namespace rangesim::tb {

// ROWS, COLUMNS, ADDRESS_BITS, SAMPLINGS, RESET_CYCLES, LATCH_CYCLES, SEARCH_CYCLES,
// OUTPUT_CYCLES. UserError naming `origin` and the key when the RTL cannot take the config (it
// streams the left and right edge, from 1-bit comparators).
VerilogParameters verilog_parameters(const LsConventionalConfig& cfg, const std::string& origin);

}  // namespace rangesim::tb
