#pragma once
// One waveform for a co-simulation: Verilator writes the RTL's VCD and SystemC (via
// systemc/common/waveform.h) the model's expected values; this puts the second into the first,
// under a top-level scope of its own, so a viewer shows them side by side on one time axis.
#include <string>
#include <vector>

namespace rangesim::tb {

// Appends the variables and value changes of `extra` to `vcd` (rewritten in place) under the
// scope `scope`, with identifiers renamed apart. std::runtime_error when a file cannot be read
// or the two time units differ.
void merge_vcd(const std::string& vcd, const std::string& extra, const std::string& scope);

// One variable of a VCD header, named as GTKWave names it: the scopes joined by '.', then the
// name with its bit range ("cosim.rtl.tdc.code_o[10:0]").
struct VcdVariable {
  std::vector<std::string> scopes;  // outermost first
  std::string name;                 // without the range
  std::string range;                // "[10:0]" or ""
  int width = 1;
  std::string full_name() const;
};

// The variables declared in the header of `vcd`, in order; std::runtime_error if unreadable.
std::vector<VcdVariable> vcd_variables(const std::string& vcd);

}  // namespace rangesim::tb
