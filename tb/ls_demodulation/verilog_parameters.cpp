#include "tb/ls_demodulation/verilog_parameters.h"

#include <fmt/format.h>

#include "core/user_error.h"
#include "tb/common/rtl_tops.h"

namespace rangesim::tb {

VerilogParameters verilog_parameters(const LsDemodulationConfig& c, const std::string& origin) {
  const int s = readout_search_cycles(c.readout);
  if (s < 1)
    throw UserError(
        fmt::format("{}: readout.row_cycles = {} leaves no cycle for the chained search after the start and "
                    "the two {}-bit addresses; allowed: row_cycles >= 2 + 2 readout.address_bits = {}",
                    origin, c.readout.row_cycles, c.readout.address_bits, 2 + 2 * c.readout.address_bits));
  // ROW_BITS = 8 (the sequencer's row counter): the harness draws at most 6 rows.
  return {{"COLUMNS", c.pixel.columns}, {"ADDRESS_BITS", c.readout.address_bits}, {"SEARCH_CYCLES", s}};
}

}  // namespace rangesim::tb

namespace rangesim::tb {

std::vector<RtlTop> ls_demodulation_rtl_tops() {
  return {{"ls_demodulation_sequencer",
           [](const ParamSet& p) { return verilog_parameters(ls_demodulation_from_params(p), p.origin()); }}};
}

}  // namespace rangesim::tb
