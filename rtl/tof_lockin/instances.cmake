# tof-lockin: gate generator, column ADC and the readout (frame sequencer + column ADC bank), with coverage for `rangesim cosim`.
# Their timing is a run-time input; the Verilog parameters are the counter widths
# (tb/tof_lockin/verilog_parameters.h), checked against instances/readout.toml.
rangesim_rtl_instance(Vlockin_gate_generator tof_lockin/lockin_gate_generator PRESET instances/readout.toml COVERAGE)
rangesim_rtl_instance(Vcolumn_adc tof_lockin/column_adc PRESET instances/readout.toml COVERAGE)
rangesim_rtl_instance(Vtof_lockin_readout tof_lockin/tof_lockin_readout PRESET instances/readout.toml COVERAGE)
