// The co-simulation targets of tof-lockin (tb/common/cosim_target.h): its readout and its blocks.
#include "tb/common/cosim_target.h"
#include "tb/common/rtl_build.h"
#include "tb/tof_lockin/lockin_gate_generator_cosim.h"
#include "tb/common/rtl_tops.h"

namespace rangesim::tb {
namespace {
CosimReport gate_generator(const CosimOptions& o) { return run_lockin_gate_generator_cosim(o); }
CosimReport column_adc(const CosimOptions& o) { return run_column_adc_cosim(o); }

// `rangesim cosim <tof-lockin preset>`: the readout (sequencer + column ADC bank) with the
// preset's timing as run-time inputs; the Verilog parameters are the counter widths, checked
// against the preset.
RtlBuildSpec preset_readout(const ParamSet& preset) {
  return {"tof_lockin",
          "tof_lockin_readout",
          rtl_top_parameters(preset, "tof_lockin_readout"),
          "tb/tof_lockin/cosim_harness.h",
          "rangesim::tb::run_tof_lockin_preset",
          {}};
}
}  // namespace

std::vector<CosimTarget> tof_lockin_cosim_targets() {
  return {
      {"tof-lockin",
       "tof-lockin readout (frame sequencer + gate generator + column ADCs) vs the tick-mode sensor kernel; "
       "ranges (eq. 2.25) from RTL codes vs the kernel's",
       {"gate_shift", "adc_code_off_by_one"},
       &run_tof_lockin_cosim},
      {"lockin_gate_generator",
       "PHASE1/2/3 (TX1/TX2/TXD) and light pulse vs LockinGateGeneratorKernel, random T0/duty/N_acc",
       {"gate_shift", "period_change_while_busy"},
       &gate_generator},
      {"column_adc",
       "single-slope column ADC counter vs ColumnAdcKernel, random resolution/inputs",
       {"adc_code_off_by_one"},
       &column_adc},
  };
}

std::vector<PresetCosim> tof_lockin_preset_cosims() {
  return {{"tof-lockin", "tof-lockin", "rtl/tof_lockin/instances/readout.toml", &preset_readout}};
}

}  // namespace rangesim::tb
