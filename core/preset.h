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
ParamSet load_preset_text(const std::string& text, const std::string& origin);

// resolve_preset + load_preset_file.
ParamSet load_preset(const std::string& id_or_path);

}  // namespace rangesim
