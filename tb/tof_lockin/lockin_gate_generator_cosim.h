#pragma once
// Co-simulation targets of the tof-lockin readout RTL against the SystemC cycle kernels
// (systemc/tof_lockin/sensor_kernel.h). Each elaborates SystemC: one run per process.
//   lockin_gate_generator  rtl/tof_lockin/lockin_gate_generator.sv vs LockinGateGeneratorKernel: gate pins every
//                          cycle, gate edges as transactions; faults: gate_shift
//   column_adc             rtl/tof_lockin/column_adc.sv vs ColumnAdcKernel: codes and conversion
//                          ends; faults: adc_code_off_by_one
//   tof-lockin             rtl/tof_lockin/tof_lockin_readout.sv (sequencer + column_adc per tap and column) vs
//                          TofLockinSensorKernel in tick mode: phases, gate pins, rows,
//                          frame boundaries, ADC codes; ranges rebuilt from the RTL codes vs
//                          the kernel's; faults: gate_shift, adc_code_off_by_one
#include <string>

#include "tb/common/cosim_target.h"

namespace rangesim::tb {

// record_path non-empty: every cycle's inputs and expected outputs go to a text file that
// tb/tof_lockin/lockin_gate_generator_replay_tb.sv replays under Icarus (ctest label iverilog).
CosimReport run_lockin_gate_generator_cosim(const CosimOptions& options, const std::string& record_path = {});
CosimReport run_column_adc_cosim(const CosimOptions& options, const std::string& record_path = {});
CosimReport run_tof_lockin_cosim(const CosimOptions& options);

}  // namespace rangesim::tb
