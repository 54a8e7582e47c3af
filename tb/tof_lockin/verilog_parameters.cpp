#include "tb/tof_lockin/verilog_parameters.h"

#include <fmt/format.h>

#include "core/user_error.h"
#include "tb/common/rtl_tops.h"

namespace rangesim::tb {
namespace {

void require_fits(const std::string& origin, const char* key, long long value, int bits, const char* what) {
  const long long max = (1LL << bits) - 1;
  if (value < 0 || value > max)
    throw UserError(fmt::format("{}: {} gives {} = {}: the tof-lockin readout RTL counts it in {} bits; allowed: 0..{}",
                                origin, key, what, value, bits, max));
}

}  // namespace

TofLockinRtlShape tof_lockin_rtl_shape(const TofLockinConfig& c, const std::string& origin) {
  const TofLockinRtlShape s;
  require_fits(origin, "source.pulse_width_s / source.duty_cycle", gate_period_cycles(c), s.cycle_bits,
               "T_rep in gate-clock cycles");
  require_fits(origin, "gates.accumulations_per_frame", c.gates.accumulations_per_frame, s.acc_bits, "N_acc");
  require_fits(origin, "readout.adc_conversion_cycles", c.readout.adc_conversion_cycles, s.cycle_bits,
               "conversion cycles");
  require_fits(origin, "readout.output_cycles_per_row", c.readout.output_cycles_per_row, s.cycle_bits,
               "output cycles per row");
  require_fits(origin, "pixel.rows", c.pixel.rows, s.row_bits, "rows");
  if (c.readout.adc_bits < 1 || c.readout.adc_bits > s.adc_bits)
    throw UserError(fmt::format("{}: readout.adc_bits = {}: the column ADC RTL has {}-bit codes; allowed: 1..{}",
                                origin, c.readout.adc_bits, s.adc_bits, s.adc_bits));
  return s;
}

namespace {

TofLockinRtlShape shape(const ParamSet& p) { return tof_lockin_rtl_shape(tof_lockin_from_params(p), p.origin()); }

VerilogParameters gate_generator(const ParamSet& p) {
  const TofLockinRtlShape s = shape(p);
  return {{"CYCLE_BITS", s.cycle_bits}, {"ACC_BITS", s.acc_bits}};
}
VerilogParameters column_adc(const ParamSet& p) {
  const TofLockinRtlShape s = shape(p);
  return {{"BITS", s.adc_bits}, {"CYCLE_BITS", s.cycle_bits}};
}
VerilogParameters sequencer(const ParamSet& p) {
  const TofLockinRtlShape s = shape(p);
  return {
      {"CYCLE_BITS", s.cycle_bits}, {"ACC_BITS", s.acc_bits}, {"ROW_BITS", s.row_bits}, {"FRAME_BITS", s.frame_bits}};
}

VerilogParameters readout(const ParamSet& p) {
  const TofLockinRtlShape s = shape(p);
  return {{"CYCLE_BITS", s.cycle_bits}, {"ACC_BITS", s.acc_bits}, {"ROW_BITS", s.row_bits},
          {"FRAME_BITS", s.frame_bits}, {"BITS", s.adc_bits},     {"CHANNELS", s.adc_channels}};
}

}  // namespace

std::vector<RtlTop> tof_lockin_rtl_tops() {
  return {{"lockin_gate_generator", &gate_generator},
          {"column_adc", &column_adc},
          {"tof_lockin_sequencer", &sequencer},
          {"tof_lockin_readout", &readout}};
}

}  // namespace rangesim::tb
