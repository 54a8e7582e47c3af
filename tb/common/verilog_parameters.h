#pragma once
// Verilog parameters of one RTL instance, in the order the top module declares them. Each sensor
// maps its config to these in one function (tb/<sensor>/verilog_parameters.h), so parameters
// flow one way: preset -> config (core/<sensor>/config.h) -> Verilog parameters.
#include <string>
#include <vector>

namespace rangesim::tb {

struct VerilogParameter {
  std::string name;  // as in the module header, e.g. "COLUMNS"
  long long value;
  bool operator==(const VerilogParameter& o) const { return name == o.name && value == o.value; }
};
using VerilogParameters = std::vector<VerilogParameter>;

// $clog2: bits to count 0..v-1 (0 for v <= 1).
constexpr int clog2(long long v) {
  int b = 0;
  while ((1LL << b) < v) ++b;
  return b;
}

// "COLUMNS=128 ADDRESS_BITS=7 ..." for messages.
inline std::string parameters_text(const VerilogParameters& p) {
  std::string s;
  for (const auto& x : p) s += (s.empty() ? "" : " ") + x.name + "=" + std::to_string(x.value);
  return s;
}

}  // namespace rangesim::tb
