// The built-in ls-conventional readout instances (rtl/CMakeLists.txt) run through the one
// harness, tb/ls_conventional/cosim_harness.h. Their configurations are defined here; the
// instances must have been verilated with verilog_parameters() of exactly these configs, which
// is checked before each run (tb/common/instance_check.h).
#include "tb/ls_conventional/cosim.h"

#include "Vls_conventional_readout.h"
#include "Vls_conventional_readout_small.h"
#include "tb/common/instance_check.h"
#include "tb/ls_conventional/cosim_harness.h"

namespace rangesim::tb {

LsConventionalConfig ls_conventional_instance_config(bool full_size) {
  LsConventionalConfig c;  // the defaults of core/ls_conventional/config.h: 365 x 375, 4 samplings
  if (full_size) return c;
  // The small instance: 8 x 16 pixels, 4-bit addresses, and a timing with LATCH_CYCLES = 2 so
  // the multi-cycle latch is exercised (56-cycle frame access).
  c.pixel.rows = 8;
  c.pixel.columns = c.search.columns = 16;
  c.search.address_bits = c.timing.address_bits = 4;
  c.timing.reset_cycles = 3;
  c.timing.latch_cycles = 2;
  c.timing.search_cycles = 2;
  c.timing.output_cycles = 5;
  return c;
}

LsConventionalCosimResult run_ls_conventional_cosim(const LsConventionalCosimOptions& options) {
  const LsConventionalConfig cfg = ls_conventional_instance_config(options.full_size);
  if (options.full_size) {
    check_instance_parameters("Vls_conventional_readout", verilog_parameters(cfg, "Vls_conventional_readout"));
    return run_ls_conventional_harness<Vls_conventional_readout>(options, cfg, "ls-conventional-full");
  }
  check_instance_parameters("Vls_conventional_readout_small",
                            verilog_parameters(cfg, "Vls_conventional_readout_small"));
  return run_ls_conventional_harness<Vls_conventional_readout_small>(options, cfg, "ls-conventional");
}

}  // namespace rangesim::tb
