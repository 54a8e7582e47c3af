# tof-lockin: gate generator, column ADC and frame sequencer, with coverage for `rangesim cosim`.
# Their timing is a run-time input; the Verilog parameters are the counter widths
# (tb/tof_lockin/verilog_parameters.h), checked against instances/readout.toml.
rangesim_rtl_instance(Vlockin_gate_generator tof_lockin/lockin_gate_generator PRESET instances/readout.toml COVERAGE)
rangesim_rtl_instance(Vcolumn_adc tof_lockin/column_adc PRESET instances/readout.toml COVERAGE)
rangesim_rtl_instance(Vtof_lockin_sequencer tof_lockin/tof_lockin_sequencer PRESET instances/readout.toml COVERAGE)
