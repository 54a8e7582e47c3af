#pragma once
// One waveform for a co-simulation: Verilator writes the RTL's VCD and SystemC (via
// systemc/common/waveform.h) the model's expected values; this puts the second into the first,
// under a top-level scope of its own, so a viewer shows them side by side on one time axis.
#include <string>

namespace rangesim::tb {

// Appends the variables and value changes of `extra` to `vcd` (rewritten in place) under the
// scope `scope`, with identifiers renamed apart. std::runtime_error when a file cannot be read
// or the two time units differ.
void merge_vcd(const std::string& vcd, const std::string& extra, const std::string& scope);

}  // namespace rangesim::tb
