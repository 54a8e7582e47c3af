#pragma once
// The co-simulation of a preset verilated at run time (tb/common/rtl_build.h) runs in a child
// process: a small executable built from the sensor's harness header and the verilated model.
// Its sc_main calls run_cosim_child with the harness; the child loads the preset, runs the
// harness and writes the CosimReport and the RTL coverage as JSON to a file, which the parent
// (`rangesim cosim`, app/cmd_cosim.cpp) reads and renders like an in-process run.
//
// Child arguments: --preset FILE --cycles N --seed S [--fault NAME] [--trace FILE] --report FILE
#include <string>

#include "core/params.h"
#include "tb/common/cosim_coverage.h"
#include "tb/common/cosim_target.h"

namespace rangesim::tb {

// The report name of a preset's run: "<sensor id>:<file name>".
inline std::string preset_target_name(const ParamSet& p) {
  const std::size_t slash = p.origin().rfind('/');
  return p.sensor_id() + ":" + (slash == std::string::npos ? p.origin() : p.origin().substr(slash + 1));
}

// A harness run on a preset's config (the verilated class fixed by the caller).
using PresetCosimRunner = CosimReport (*)(const ParamSet& preset, const CosimOptions& options);

// sc_main of the child: 0 when the report was written (mismatches or not), 2 after a UserError,
// 1 after any other error; errors go into the report file too, so the parent can repeat them.
int run_cosim_child(int argc, char** argv, PresetCosimRunner runner);

// The report file: {"report": {...}, "coverage": {...}} or {"error": "...", "user_error": bool}.
std::string cosim_report_file_text(const CosimReport& r, const RtlCoverage& cov);
std::string cosim_error_file_text(const std::string& message, bool user_error);
// Parses a report file; an error file throws UserError (user_error) or std::runtime_error.
void parse_cosim_report_file(const std::string& text, CosimReport& r, RtlCoverage& cov);

}  // namespace rangesim::tb
