# ls-demodulation: its frame sequencer with the address search (rtl/common/), from the chip's
# preset (instances/readout.toml), with coverage for `rangesim cosim`.
rangesim_rtl_instance(Vls_demodulation_sequencer ls_demodulation/ls_demodulation_sequencer
  PRESET instances/readout.toml COVERAGE)
