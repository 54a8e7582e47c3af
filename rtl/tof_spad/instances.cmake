# tof-spad: one TDC group (row sequencer, tdc.sv, tdc_histogram.sv) of the chip's preset
# (instances/tdc_group.toml), with coverage for `rangesim cosim`.
rangesim_rtl_instance(Vtof_spad_sequencer tof_spad/tof_spad_sequencer PRESET instances/tdc_group.toml COVERAGE)
