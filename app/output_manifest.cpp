#include "app/output_manifest.h"

#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "app/file_replace.h"

namespace rangesim::app {

namespace fs = std::filesystem;

namespace {

constexpr const char* kMagic = "rangesim-output 1";

bool plain_name(const std::string& name) {
  return !name.empty() && name[0] != '.' && name.find('/') == std::string::npos;
}

}  // namespace

std::optional<OutputManifest> read_manifest(const std::string& dir) {
  std::ifstream in(fs::path(dir) / kManifestName);
  std::string line;
  if (!in || !std::getline(in, line) || line != kMagic) return std::nullopt;
  OutputManifest m;
  while (std::getline(in, line)) {
    const auto space = line.find(' ');
    const std::string key = line.substr(0, space), value = space == std::string::npos ? "" : line.substr(space + 1);
    if (key == "kind")
      m.kind = value;
    else if (key == "file" && plain_name(value))
      m.files.push_back(value);
  }
  return m;
}

void write_manifest(const std::string& dir, const OutputManifest& m, const std::string& staged_prefix) {
  std::ostringstream text;
  text << kMagic << "\nkind " << m.kind << "\n";
  for (const auto& f : m.files) text << "file " << f << "\n";
  const fs::path tmp = staged_prefix + kManifestName;
  {
    std::ofstream out(tmp, std::ios::binary);
    out << text.str();
    out.close();
    if (!out) throw std::runtime_error(fmt::format("cannot write {}", tmp.string()));
  }
  replace_file(tmp.string(), (fs::path(dir) / kManifestName).string());
}

}  // namespace rangesim::app
