#pragma once
// The built-in instances of rtl/CMakeLists.txt must have been verilated with the Verilog
// parameters of the configs their harnesses run: verilog_parameters(config) is the one map, and
// rtl/instance_parameters.h (generated) lists what CMake passed. A difference is a programmer
// error (the two files disagree), not bad input.
#include <algorithm>
#include <sstream>
#include <stdexcept>
#include <string>

#include "rtl/instance_parameters.h"
#include "tb/common/verilog_parameters.h"

namespace rangesim::tb {

// Throws std::logic_error unless every parameter in `want` is what `prefix` was verilated with
// (parameters CMake left at their Verilog default must equal that default: listed in `want`
// only if passed).
inline void check_instance_parameters(const std::string& prefix, const VerilogParameters& want) {
  for (const auto& inst : rtl::kInstanceParameters) {
    if (prefix != inst.prefix) continue;
    VerilogParameters have;
    std::istringstream in(inst.parameters);
    for (std::string kv; in >> kv;) {
      const std::size_t eq = kv.find('=');
      have.push_back({kv.substr(0, eq), std::stoll(kv.substr(eq + 1))});
    }
    auto by_name = [](const VerilogParameter& a, const VerilogParameter& b) { return a.name < b.name; };
    VerilogParameters w = want;
    std::sort(w.begin(), w.end(), by_name);
    std::sort(have.begin(), have.end(), by_name);
    if (w != have)
      throw std::logic_error(prefix + " was verilated with " + parameters_text(have) +
                             " (rtl/CMakeLists.txt) but its harness config needs " + parameters_text(w));
    return;
  }
  throw std::logic_error(prefix + " is not an instance of rtl/CMakeLists.txt");
}

}  // namespace rangesim::tb
