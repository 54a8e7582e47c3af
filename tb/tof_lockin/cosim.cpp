// The built-in tof-lockin readout instance (rtl/tof_lockin/instances.cmake) through the one
// harness, tb/tof_lockin/cosim_harness.h: timings drawn from their ranges within the counter
// widths of its instance preset (random_tof_lockin_setup, tb/tof_lockin/stimulus.h).
#include "Vtof_lockin_readout.h"
#include "tb/common/instance_preset.h"
#include "tb/tof_lockin/cosim_harness.h"
#include "tb/tof_lockin/lockin_gate_generator_cosim.h"

namespace rangesim::tb {

CosimReport run_tof_lockin_cosim(const CosimOptions& o) {
  const ParamSet preset = instance_preset("Vtof_lockin_readout");
  const TofLockinRtlShape shape = tof_lockin_rtl_shape(tof_lockin_from_params(preset), preset.origin());
  std::mt19937_64 rng(o.seed);
  return run_tof_lockin_harness<Vtof_lockin_readout>(o, random_tof_lockin_setup(o.cycles, o.seed, rng), shape,
                                                     "tof-lockin");
}

}  // namespace rangesim::tb
