// The built-in ls-conventional readout instances (rtl/CMakeLists.txt) run through the one
// harness, tb/ls_conventional/cosim_harness.h. Their configurations are defined here; the
// instances must have been verilated with verilog_parameters() of exactly these configs, which
// is checked before each run (rtl/ls_conventional_params.h holds what CMake passed).
#include "tb/ls_conventional/cosim.h"

#include <stdexcept>

#include "Vls_conventional_readout.h"
#include "Vls_conventional_readout_small.h"
#include "rtl/ls_conventional_params.h"
#include "tb/ls_conventional/cosim_harness.h"

namespace rangesim::tb {
namespace {

VerilogParameters instance_parameters(const rtl::LsConventionalRtlParams& p) {
  return {{"ROWS", p.rows},
          {"COLUMNS", p.columns},
          {"ADDRESS_BITS", p.address_bits},
          {"SAMPLINGS", p.samplings},
          {"RESET_CYCLES", p.reset_cycles},
          {"LATCH_CYCLES", p.latch_cycles},
          {"SEARCH_CYCLES", p.search_cycles},
          {"OUTPUT_CYCLES", p.output_cycles}};
}

// A programmer error, not bad input: rtl/CMakeLists.txt and ls_conventional_instance_config
// disagree.
void check_instance(const LsConventionalConfig& cfg, const rtl::LsConventionalRtlParams& p) {
  const VerilogParameters want = verilog_parameters(cfg, p.prefix), have = instance_parameters(p);
  if (want != have)
    throw std::logic_error(std::string(p.prefix) + " was verilated with " + parameters_text(have) +
                           " but its harness config needs " + parameters_text(want));
}

}  // namespace

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
    check_instance(cfg, rtl::kLsConventionalFull);
    return run_ls_conventional_harness<Vls_conventional_readout>(options, cfg, "ls-conventional-full");
  }
  check_instance(cfg, rtl::kLsConventionalSmall);
  return run_ls_conventional_harness<Vls_conventional_readout_small>(options, cfg, "ls-conventional");
}

}  // namespace rangesim::tb
