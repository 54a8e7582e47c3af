#pragma once
// Finding, loading and validating sensor presets (presets/*.toml).
#include <string>
#include <vector>

#include "core/params.h"
#include "core/sensor_registry.h"

namespace rangesim {

// Directories searched for `<id>.toml`: $RANGESIM_PRESET_DIR, the installed share dir, and the
// source tree's presets/ (so a fresh build works without installing).
std::vector<std::string> preset_search_path();

// A preset id or a path to a TOML file -> path of an existing file; UserError if none.
std::string resolve_preset(const std::string& id_or_path);

// Loads and validates a preset file against its sensor's schema (reads it, then
// load_preset_text with the path as origin).
ParamSet load_preset_file(const std::string& path);

// Parses and validates preset TOML text against its sensor's schema. `origin` names the text in
// every message (a file path, "<stdin>", ...) and becomes ParamSet::origin(). Any bad input, of
// whatever bytes, throws UserError and nothing else.
//
// A preset may inherit: `base = "<preset id or path>"` (a path relative to the file's folder) at
// the top, then only the keys it changes, each as a plain value (`clock_Hz = 50e6`, source
// "user") or as { value, source }; sensor.id may then be left out. Each value remembers the file
// it came from (ParamValue::file). A circle of bases is refused. The sensor's cross-key checks
// (validate_preset) run before the set is returned, so every command refuses the same presets.
ParamSet load_preset_text(const std::string& text, const std::string& origin);

// The sensor's cross-key checks (its config built from the set; core/sensor_registry.h): throws
// UserError naming the file and both keys.
void validate_preset(const ParamSet& set);

// `--set KEY=VALUE` assignments, applied in order after the preset with the same validation and
// messages (range, type, choices), then the cross-key checks again. Source "command line --set".
void apply_settings(ParamSet& set, const std::vector<std::string>& assignments);

// resolve_preset + load_preset_file.
ParamSet load_preset(const std::string& id_or_path);

}  // namespace rangesim
