#pragma once
// Run-time verilation: `rangesim cosim <preset.toml>` co-simulates the RTL of the preset's own
// architecture. The sensor maps the preset's config to Verilog parameters
// (tb/<sensor>/verilog_parameters.h); this file verilates the top module with them, compiles it
// together with a generated sc_main that calls the sensor's harness (a header, templated on the
// verilated class) and links the build tree's static libraries. The executable is cached under
// $RANGESIM_RTL_CACHE (default $XDG_CACHE_HOME/rangesim/rtl, else ~/.cache/rangesim/rtl) in a
// folder named by a hash of the Verilog parameters, the RTL and harness sources, the libraries
// and the compiler, so a second run with the same parameters starts at once. Each build goes
// to a temporary folder (.tmp-<hash>-*) that is renamed when complete: a killed build leaves no
// half-made entry (its folder is never used and is removed once a day old).
#include <string>
#include <vector>

#include "core/params.h"
#include "tb/common/cosim_child.h"
#include "tb/common/verilog_parameters.h"

namespace rangesim::tb {

struct RtlBuildSpec {
  std::string folder;  // rtl/<folder>/ and tb/<folder>/, e.g. "ls_conventional"
  std::string top;     // top module, rtl/<folder>/<top>.sv
  VerilogParameters parameters;
  std::string harness_header;  // included by the generated sc_main, e.g. "tb/ls_conventional/cosim_harness.h"
  std::string runner;          // function template of that header: PresetCosimRunner once instantiated
  // A user's Verilog (`cosim --rtl FILE.sv`), read before rangesim's: its modules replace the
  // rangesim blocks of the same name (absolute paths; checked by check_user_rtl first).
  std::vector<std::string> user_files;
};

// A sensor whose readout is co-simulated at a preset's own parameters (`rangesim cosim
// <preset.toml>`). Each sensor lists its own in tb/<sensor>/cosim_targets.cpp.
struct PresetCosim {
  const char* sensor;                            // sensor id of the presets it takes
  const char* target;                            // the built-in target it generalises: same harness, same faults
  const char* instance_preset;                   // its built-in instance's preset, relative to the source tree
  RtlBuildSpec (*spec)(const ParamSet& preset);  // UserError when the RTL cannot take the preset
};
const std::vector<PresetCosim>& preset_cosims();  // tb/common/cosim_targets.cpp
// The one whose built-in target is `target` (nullptr if none), and its instance preset's path.
const PresetCosim* preset_cosim_of_target(const std::string& target);
std::string instance_preset_path(const PresetCosim& pc);

// The rangesim blocks the user's files of `spec` replace inside its top (at least one; with
// `top` non-empty, that one must be among them), each checked against its port contract at the
// preset's parameters (tb/common/rtl_ports.h). UserError naming the file, module and port.
std::vector<std::string> check_user_rtl(const RtlBuildSpec& spec, const ParamSet& preset, const std::string& top);

// Keeps the cache under $RANGESIM_RTL_CACHE_MAX_MB (default 2048): removes the entries of
// `root` used longest ago (a use touches its folder), never `keep`. UserError for a bad bound.
void bound_rtl_cache(const std::string& root, const std::string& keep);

// Path of the co-simulation executable of `spec`, verilated and compiled now unless cached.
// Progress on stderr. UserError (exit 2) when verilator or the C++ compiler is missing or the
// build fails (the last lines of its log are printed).
std::string rtl_cosim_executable(const RtlBuildSpec& spec);

// Runs the executable on the preset (child arguments of tb/common/cosim_child.h); its stdout and
// stderr go to this process's stderr. Errors of the child are rethrown (UserError stays UserError).
// `settings`: --set KEY=VALUE assignments the child applies after the preset (core/preset.h).
void run_rtl_cosim(const std::string& executable, const std::string& preset_path,
                   const std::vector<std::string>& settings, const CosimOptions& options, CosimReport& report,
                   RtlCoverage& coverage);

}  // namespace rangesim::tb
