#include "tb/tof_spad/verilog_parameters.h"

#include <fmt/format.h>

#include <algorithm>

#include "core/user_error.h"
#include "tb/common/rtl_tops.h"

namespace rangesim::tb {

TofSpadRtlShape tof_spad_rtl_shape(const TofSpadConfig& c, const std::string& origin) {
  // Up to 16 columns per group: the harness packs a cycle's hits, interpolator phases and
  // corrections of the group into fixed-size words (tb/tof_spad/cosim_harness.h).
  if (c.tdc.columns_per_tdc < 1 || c.tdc.columns_per_tdc > 16)
    throw UserError(
        fmt::format("{}: tdc.columns_per_tdc = {}: allowed for co-simulation: 1..16", origin, c.tdc.columns_per_tdc));
  // The histogram memory holds CPT x 2^bits words.
  if (c.tdc.bits < 1 || c.tdc.bits > 12)
    throw UserError(fmt::format("{}: tdc.bits = {}: allowed for co-simulation: 1..12", origin, c.tdc.bits));
  TofSpadRtlShape s;
  s.cpt = c.tdc.columns_per_tdc;
  s.col_bits = std::max(1, clog2(s.cpt));
  s.bin_bits = c.tdc.bits + 1;
  s.codes_max = 1 << c.tdc.bits;
  return s;
}

VerilogParameters verilog_parameters(const TofSpadConfig& cfg, const std::string& origin) {
  const TofSpadRtlShape s = tof_spad_rtl_shape(cfg, origin);
  return {{"CPT", s.cpt},
          {"COL_BITS", s.col_bits},
          {"BIN_BITS", s.bin_bits},
          {"CODES_MAX", s.codes_max},
          {"FINE_BITS", s.fine_bits},
          {"CORR_BITS", s.corr_bits},
          {"COUNT_BITS", s.count_bits},
          {"ROW_BITS", s.row_bits},
          {"LASER_BITS", s.laser_bits}};
}

}  // namespace rangesim::tb

namespace rangesim::tb {

std::vector<RtlTop> tof_spad_rtl_tops() {
  return {{"tof_spad_sequencer",
           [](const ParamSet& p) { return verilog_parameters(tof_spad_from_params(p), p.origin()); }}};
}

}  // namespace rangesim::tb
