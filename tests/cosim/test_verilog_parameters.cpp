// verilog_parameters(config): the one map from a sensor's config to its RTL's Verilog parameters
// (tb/<sensor>/verilog_parameters.h), on the fixtures of tests/cosim/presets and on configs the
// RTL cannot take (UserError naming the key).
#include <gtest/gtest.h>

#include <string>

#include "core/ls_conventional/config.h"
#include "core/ls_demodulation/config.h"
#include "core/preset.h"
#include "core/tof_spad/config.h"
#include "core/user_error.h"
#include "tb/ls_conventional/verilog_parameters.h"
#include "tb/ls_demodulation/verilog_parameters.h"
#include "tb/tof_spad/verilog_parameters.h"

namespace rangesim::tb {
namespace {

const std::string kPresets = RANGESIM_COSIM_PRESET_DIR;

std::string text_of(const VerilogParameters& p) { return parameters_text(p); }

TEST(VerilogParameters, LsConventionalFixture) {
  const auto cfg = ls_conventional_from_params(load_preset(kPresets + "/ls-conventional-128x64.toml"));
  EXPECT_EQ(text_of(verilog_parameters(cfg, "x")),
            "ROWS=64 COLUMNS=128 ADDRESS_BITS=7 SAMPLINGS=3 RESET_CYCLES=4 LATCH_CYCLES=1 SEARCH_CYCLES=2 "
            "OUTPUT_CYCLES=12");
}

TEST(VerilogParameters, TofSpadFixture) {
  const auto cfg = tof_spad_from_params(load_preset(kPresets + "/tof-spad-8-columns-per-tdc.toml"));
  EXPECT_EQ(text_of(verilog_parameters(cfg, "x")),
            "CPT=8 COL_BITS=3 BIN_BITS=11 CODES_MAX=1024 FINE_BITS=16 CORR_BITS=3 COUNT_BITS=16 ROW_BITS=8 "
            "LASER_BITS=24");
}

TEST(VerilogParameters, LsDemodulationFixture) {
  const auto cfg = ls_demodulation_from_params(load_preset(kPresets + "/ls-demodulation-64-columns.toml"));
  EXPECT_EQ(text_of(verilog_parameters(cfg, "x")), "COLUMNS=64 ADDRESS_BITS=6 SEARCH_CYCLES=28");
}

template <class F>
std::string user_error_of(F f) {
  try {
    f();
  } catch (const UserError& e) {
    return e.what();
  }
  return "";
}

TEST(VerilogParameters, ConfigsTheRtlCannotTakeNameTheKey) {
  LsConventionalConfig ls;
  ls.timing.addresses_per_sampling = 1;
  EXPECT_NE(user_error_of([&] { verilog_parameters(ls, "p.toml"); }).find("p.toml: timing.addresses_per_sampling"),
            std::string::npos);
  TofSpadConfig spad;
  spad.tdc.columns_per_tdc = 32;
  EXPECT_NE(user_error_of([&] { verilog_parameters(spad, "p.toml"); }).find("tdc.columns_per_tdc = 32: allowed"),
            std::string::npos);
  LsDemodulationConfig demod;
  demod.readout.row_cycles = 15;  // 1 + 2 x 7 bits: no cycle left for the search
  EXPECT_NE(user_error_of([&] { verilog_parameters(demod, "p.toml"); }).find("readout.row_cycles = 15"),
            std::string::npos);
}

}  // namespace
}  // namespace rangesim::tb
