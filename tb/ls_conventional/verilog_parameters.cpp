#include "tb/ls_conventional/verilog_parameters.h"

#include <fmt/format.h>

#include "core/user_error.h"

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
