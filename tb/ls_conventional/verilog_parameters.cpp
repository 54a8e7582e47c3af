#include "tb/ls_conventional/verilog_parameters.h"

#include <fmt/format.h>

#include "core/user_error.h"
#include "tb/common/rtl_tops.h"

namespace rangesim::tb {

VerilogParameters verilog_parameters(const LsConventionalConfig& c, const std::string& origin) {
  // The readout RTL streams exactly the two edge addresses of a row (centre_processor sums left
  // + right) and latches 1-bit comparator decisions (cmp_i).
  if (c.timing.addresses_per_sampling != 2)
    throw UserError(
        fmt::format("{}: timing.addresses_per_sampling = {}: the readout RTL streams the left and right "
                    "edge; allowed for co-simulation: 2",
                    origin, c.timing.addresses_per_sampling));
  if (c.comparator.adc_bits != 1)
    throw UserError(
        fmt::format("{}: comparator.adc_bits = {}: the readout RTL takes 1-bit comparator decisions; "
                    "allowed for co-simulation: 1",
                    origin, c.comparator.adc_bits));
  return {{"ROWS", c.pixel.rows},
          {"COLUMNS", c.pixel.columns},
          {"ADDRESS_BITS", c.search.address_bits},
          {"SAMPLINGS", c.multisampling.samplings},
          {"RESET_CYCLES", c.timing.reset_cycles},
          {"LATCH_CYCLES", c.timing.latch_cycles},
          {"SEARCH_CYCLES", c.timing.search_cycles},
          {"OUTPUT_CYCLES", c.timing.output_cycles}};
}

}  // namespace rangesim::tb

namespace rangesim::tb {
namespace {

// The readout's parameters that one of its blocks takes (the block gets them from the readout
// when it is instantiated inside it, rtl/ls_conventional/ls_conventional_readout.sv).
VerilogParameters subset(const ParamSet& p, std::initializer_list<const char*> names) {
  VerilogParameters out;
  for (const auto& x : verilog_parameters(ls_conventional_from_params(p), p.origin()))
    for (const char* n : names)
      if (x.name == n) out.push_back(x);
  return out;
}

VerilogParameters readout(const ParamSet& p) { return verilog_parameters(ls_conventional_from_params(p), p.origin()); }
VerilogParameters address_search(const ParamSet& p) { return subset(p, {"COLUMNS", "ADDRESS_BITS", "SEARCH_CYCLES"}); }
VerilogParameters centre_processor(const ParamSet& p) { return subset(p, {"ADDRESS_BITS", "SAMPLINGS"}); }
VerilogParameters multisampling_sequencer(const ParamSet& p) {
  return subset(p, {"SAMPLINGS", "RESET_CYCLES", "LATCH_CYCLES", "SEARCH_CYCLES", "ADDRESS_BITS", "OUTPUT_CYCLES"});
}

}  // namespace

std::vector<RtlTop> ls_conventional_rtl_tops() {
  return {{"ls_conventional_readout", &readout},
          {"address_search", &address_search},
          {"centre_processor", &centre_processor},
          {"multisampling_sequencer", &multisampling_sequencer}};
}

}  // namespace rangesim::tb
