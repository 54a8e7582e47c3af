#pragma once
// Which files of an output folder are rangesim's: DIR/.rangesim-manifest names the command that
// wrote them ("evaluate", "simulate", ...) and lists them. A new run of that command replaces
// those files and keeps everything else (the user's own files); another command is refused
// without --force, so one command never silently wipes another's results. The manifest holds
// nothing that differs between runs with the same outputs (no command line, no time), so equal
// runs leave equal folders.
#include <optional>
#include <string>
#include <vector>

namespace rangesim::app {

struct OutputManifest {
  std::string kind;                // the command that wrote the files
  std::vector<std::string> files;  // plain file names in the folder
};

inline constexpr const char* kManifestName = ".rangesim-manifest";

// The manifest of `dir`, if it has a readable one. Names that are not plain file names (a path,
// a hidden file) are dropped, so a hand-edited manifest cannot point a run at other files.
std::optional<OutputManifest> read_manifest(const std::string& dir);

// Writes the manifest through a temporary file named `staged_prefix` + its name (on the same file
// system: DIR/.staging-<pid>.) and a rename: at any instant the folder has a complete manifest.
void write_manifest(const std::string& dir, const OutputManifest& m, const std::string& staged_prefix);

}  // namespace rangesim::app
