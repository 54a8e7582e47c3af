#pragma once
// Helpers shared by the subcommands: flag parsing with user-facing errors, exit codes.
#include <string>
#include <vector>

#include "core/params.h"

namespace rangesim::app {

// Exit codes of the rangesim command (documented in --help and README).
inline constexpr int kExitOk = 0;
inline constexpr int kExitInternal = 1;     // a bug or an I/O failure after validation
inline constexpr int kExitBadInput = 2;     // bad preset, flag or output directory
inline constexpr int kExitNotModelled = 3;  // the sensor has no model for this command yet

// Thrown for a sensor that has no model yet for the subcommand.
struct NotModelled {
  std::string message;
};

struct GridAxis {
  double lo = 0;
  double hi = 0;
  int n = 0;
};

// Parses "LO:HI:N" (volts, log-spaced): LO > 0, HI >= LO, finite, 1 <= N <= 10000; a
// UserError names `flag` and the allowed form otherwise.
GridAxis parse_grid_axis(const std::string& text, const std::string& flag);

// Loads a preset by id or path, applies the `--set KEY=VALUE` assignments (core/preset.h,
// apply_settings) and checks that `command` has a model for its sensor.
ParamSet load_modelled_preset(const std::string& id_or_path, const std::string& command,
                              const std::vector<std::string>& settings = {});
// The check of load_modelled_preset on a loaded preset: throws NotModelled naming `command`.
void require_modelled(const ParamSet& params, const std::string& command);

}  // namespace rangesim::app
