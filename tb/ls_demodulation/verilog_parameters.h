#pragma once
// The one map from an ls-demodulation config to the Verilog parameters of
// rtl/ls_demodulation/ls_demodulation_sequencer.sv (COLUMNS, ADDRESS_BITS, SEARCH_CYCLES; the
// counter widths are the RTL's and bound its run-time inputs). Used for the built-in instance (at
// build time, from rtl/ls_demodulation/instances/readout.toml) and for a preset's own
// (`rangesim cosim <preset.toml>`).
#include <string>

#include "core/ls_demodulation/config.h"
#include "tb/common/verilog_parameters.h"

namespace rangesim::tb {

// UserError naming `origin` and the keys when the RTL cannot take the config.
VerilogParameters verilog_parameters(const LsDemodulationConfig& cfg, const std::string& origin);

}  // namespace rangesim::tb
