// The built-in ls-conventional readout instances (rtl/ls_conventional/instances.cmake) run through
// the one harness, tb/ls_conventional/cosim_harness.h, with the configuration of the instance
// preset each was verilated from (rtl/ls_conventional/instances/).
#include "tb/ls_conventional/cosim.h"

#include "Vls_conventional_readout.h"
#include "Vls_conventional_readout_small.h"
#include "tb/common/instance_preset.h"
#include "tb/ls_conventional/cosim_harness.h"

namespace rangesim::tb {

LsConventionalConfig ls_conventional_instance_config(bool full_size) {
  return ls_conventional_from_params(
      instance_preset(full_size ? "Vls_conventional_readout" : "Vls_conventional_readout_small"));
}

LsConventionalCosimResult run_ls_conventional_cosim(const LsConventionalCosimOptions& options) {
  const LsConventionalConfig cfg = ls_conventional_instance_config(options.full_size);
  if (options.full_size)
    return run_ls_conventional_harness<Vls_conventional_readout>(options, cfg, "ls-conventional-full");
  return run_ls_conventional_harness<Vls_conventional_readout_small>(options, cfg, "ls-conventional");
}

}  // namespace rangesim::tb
