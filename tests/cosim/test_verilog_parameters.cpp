// verilog_parameters(config): the one map from a sensor's config to its RTL's Verilog parameters
// (tb/<sensor>/verilog_parameters.h), on the fixtures of tests/cosim/presets and on configs the
// RTL cannot take (UserError naming the key).
#include <gtest/gtest.h>

#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "core/ls_conventional/config.h"
#include "core/ls_demodulation/config.h"
#include "core/preset.h"
#include "core/tof_spad/config.h"
#include "core/user_error.h"
#include "rtl/instance_presets.h"
#include "tb/common/instance_preset.h"
#include "tb/common/rtl_build.h"
#include "tb/common/rtl_tops.h"
#include "tb/ls_conventional/verilog_parameters.h"
#include "tb/ls_demodulation/verilog_parameters.h"
#include "tb/tof_lockin/verilog_parameters.h"
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

// Every built-in instance was verilated with the Verilog parameters its instance preset maps to:
// the .params.f the build wrote (rtl/CMakeLists.txt) holds exactly rtl_top_parameters() of the
// preset the harness runs (tb/common/instance_preset.h).
TEST(VerilogParameters, BuiltInInstancesAreTheirPresets) {
  const std::pair<const char*, const char*> tops[] = {
      {"Vls_conventional_readout_small", "ls_conventional_readout"},
      {"Vls_conventional_readout", "ls_conventional_readout"},
      {"Vcentre_processor_small", "centre_processor"},
      {"Vmultisampling_sequencer_small", "multisampling_sequencer"},
      {"Vaddress_search_small", "address_search"},
      {"Vaddress_search", "address_search"},
      {"Vls_demodulation_sequencer", "ls_demodulation_sequencer"},
      {"Vtof_spad_sequencer", "tof_spad_sequencer"},
      {"Vlockin_gate_generator", "lockin_gate_generator"},
      {"Vcolumn_adc", "column_adc"},
      {"Vtof_lockin_readout", "tof_lockin_readout"},
  };
  EXPECT_EQ(std::size(rtl::kInstancePresets), std::size(tops));
  for (const auto& [prefix, top] : tops) {
    std::ifstream in(std::string(RANGESIM_RTL_BINARY_DIR) + "/" + prefix + "/" + prefix + ".params.f");
    ASSERT_TRUE(in) << prefix;
    std::string built, line;
    while (std::getline(in, line))
      if (line.rfind("-G", 0) == 0) built += (built.empty() ? "" : " ") + line.substr(2);
    EXPECT_EQ(built, parameters_text(rtl_top_parameters(instance_preset(prefix), top))) << prefix;
  }
  // The small readout is what its preset says, not the chip.
  EXPECT_EQ(
      parameters_text(rtl_top_parameters(instance_preset("Vls_conventional_readout_small"), "ls_conventional_readout")),
      "ROWS=8 COLUMNS=16 ADDRESS_BITS=4 SAMPLINGS=4 RESET_CYCLES=3 LATCH_CYCLES=2 SEARCH_CYCLES=2 "
      "OUTPUT_CYCLES=5");
}

TEST(VerilogParameters, TopsOfAnotherSensorAreRefused) {
  const ParamSet spad = load_preset("tof-spad");
  const std::string e = user_error_of([&] { rtl_top_parameters(spad, "ls_conventional_readout"); });
  EXPECT_NE(e.find("has no RTL top 'ls_conventional_readout'"), std::string::npos) << e;
  EXPECT_NE(e.find("tof_spad_sequencer"), std::string::npos) << e;
}

// tof-lockin's timing is a run-time input of its RTL: a preset must fit the counter widths.
TEST(VerilogParameters, TofLockinTimingMustFitTheCounters) {
  TofLockinConfig c = tof_lockin_from_params(load_preset("tof-lockin"));
  EXPECT_EQ(tof_lockin_rtl_shape(c, "p.toml").cycle_bits, 16);
  c.gates.accumulations_per_frame = 1LL << 20;
  EXPECT_NE(user_error_of([&] { tof_lockin_rtl_shape(c, "p.toml"); })
                .find("p.toml: gates.accumulations_per_frame gives N_acc = 1048576: the tof-lockin readout RTL counts "
                      "it in 20 bits; allowed: 0..1048575"),
            std::string::npos);
  c = tof_lockin_from_params(load_preset("tof-lockin"));
  c.readout.adc_bits = 14;
  EXPECT_NE(user_error_of([&] { tof_lockin_rtl_shape(c, "p.toml"); }).find("readout.adc_bits = 14"), std::string::npos);
  c = tof_lockin_from_params(load_preset("tof-lockin"));
  c.source.duty_cycle = 1e-4;  // T_rep = 10^5 gate-clock cycles
  EXPECT_NE(user_error_of([&] { tof_lockin_rtl_shape(c, "p.toml"); }).find("T_rep in gate-clock cycles = 100000"),
            std::string::npos);
}

}  // namespace
}  // namespace rangesim::tb

namespace rangesim::tb {
namespace {

// The run-time RTL cache stays under its bound: the entries used longest ago go first, the one
// just used never; a bound that is no whole number of MB is refused.
TEST(RtlCache, OldestEntriesGoPastTheBound) {
  namespace fs = std::filesystem;
  const fs::path root = fs::path(testing::TempDir()) / ("rtl_cache_bound_" + std::to_string(::getpid()));
  fs::remove_all(root);
  const auto now = fs::file_time_type::clock::now();
  for (int i = 0; i < 4; ++i) {
    const fs::path e = root / ("entry" + std::to_string(i));
    fs::create_directories(e);
    std::ofstream(e / "cosim", std::ios::binary) << std::string(700 * 1024, 'x');  // 0.7 MB
    fs::last_write_time(e, now - std::chrono::hours(10 - i));                     // entry0 oldest
  }
  fs::last_write_time(root / "entry0", now - std::chrono::hours(20));
  ::setenv("RANGESIM_RTL_CACHE_MAX_MB", "2", 1);
  bound_rtl_cache(root.string(), (root / "entry0").string());  // keep the oldest: it was just used
  EXPECT_TRUE(fs::exists(root / "entry0"));
  EXPECT_FALSE(fs::exists(root / "entry1"));  // 2.8 MB -> 2.1 MB -> still over: entry2 goes too
  EXPECT_FALSE(fs::exists(root / "entry2"));
  EXPECT_TRUE(fs::exists(root / "entry3"));
  ::setenv("RANGESIM_RTL_CACHE_MAX_MB", "lots", 1);
  EXPECT_NE(user_error_of([&] { bound_rtl_cache(root.string(), ""); }).find("RANGESIM_RTL_CACHE_MAX_MB = 'lots'"),
            std::string::npos);
  ::unsetenv("RANGESIM_RTL_CACHE_MAX_MB");
  fs::remove_all(root);
}

}  // namespace
}  // namespace rangesim::tb
