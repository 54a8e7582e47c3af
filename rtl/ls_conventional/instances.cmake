# ls-conventional: its readout (sequencer + per-row comparator latches, address_search,
# centre_processor) and its blocks, each from an instance preset (rtl/CMakeLists.txt).
# instances/small.toml: 8 x 16 with a two-cycle latch, with coverage, for `rangesim cosim`;
# instances/full.toml: the chip (375 x 365), uninstrumented, for the full-size cosim and bench.
rangesim_rtl_instance(Vls_conventional_readout_small ls_conventional/ls_conventional_readout
  PRESET instances/small.toml COVERAGE)
rangesim_rtl_instance(Vcentre_processor_small ls_conventional/centre_processor PRESET instances/small.toml COVERAGE)
rangesim_rtl_instance(Vmultisampling_sequencer_small ls_conventional/multisampling_sequencer
  PRESET instances/small.toml COVERAGE)
rangesim_rtl_instance(Vaddress_search_small common/address_search PRESET instances/small.toml COVERAGE)
rangesim_rtl_instance(Vls_conventional_readout ls_conventional/ls_conventional_readout PRESET instances/full.toml)
rangesim_rtl_instance(Vaddress_search common/address_search PRESET instances/full.toml)
