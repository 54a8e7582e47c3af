#include "app/output_dir.h"

#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <unistd.h>

#include "core/user_error.h"

namespace fs = std::filesystem;

namespace rangesim::app {

void check_output_file(const std::string& path, const std::string& flag) {
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (ec && ec != std::errc::no_such_file_or_directory)
    throw UserError(fmt::format("{} {}: cannot use it as an output file ({}); allowed: a new or regular file", flag,
                                path, ec.message()));
  if (fs::exists(st) && !fs::is_regular_file(st))
    throw UserError(fmt::format("{} {}: exists and is {}; allowed: a new or regular file (which is replaced)", flag,
                                path, fs::is_directory(st) ? "a directory" : "not a regular file"));
}

OutputDir::OutputDir(const std::string& dir, const std::string& flag) : dir_(dir) {
  std::error_code ec;
  if (fs::exists(dir_, ec) && !fs::is_directory(dir_, ec))
    throw UserError(fmt::format("{} {}: exists and is not a directory", flag, dir_));
  if (!fs::exists(dir_, ec)) {
    fs::create_directories(dir_, ec);
    if (ec) throw UserError(fmt::format("{} {}: cannot create output directory ({})", flag, dir_, ec.message()));
    created_dir_ = true;
  }
  staging_ = (fs::path(dir_) / fmt::format(".staging-{}", ::getpid())).string();
  fs::create_directory(staging_, ec);
  if (ec || ::access(dir_.c_str(), W_OK) != 0) {
    if (created_dir_) fs::remove(dir_, ec);
    throw UserError(fmt::format("{} {}: output directory is not writable", flag, dir_));
  }
}

OutputDir::~OutputDir() {
  if (committed_) return;
  std::error_code ec;
  fs::remove_all(staging_, ec);
  if (created_dir_ && fs::is_empty(dir_, ec)) fs::remove(dir_, ec);
}

std::string OutputDir::staged(const std::string& name) {
  names_.push_back(name);
  return (fs::path(staging_) / name).string();
}

std::string OutputDir::scratch(const std::string& name) const { return (fs::path(staging_) / name).string(); }

void OutputDir::write(const std::string& name, const std::string& text) {
  const std::string path = staged(name);
  std::ofstream out(path, std::ios::binary);
  out << text;
  out.close();
  if (!out) throw std::runtime_error(fmt::format("cannot write {}", path));
}

std::vector<std::string> OutputDir::commit() {
  std::vector<std::string> written;
  for (const auto& name : names_) {
    const fs::path from = fs::path(staging_) / name;
    if (!fs::exists(from)) continue;  // optional outputs (plots without gnuplot)
    const fs::path to = fs::path(dir_) / name;
    fs::rename(from, to);
    written.push_back(to.string());
  }
  std::error_code ec;
  fs::remove_all(staging_, ec);
  committed_ = true;
  return written;
}

}  // namespace rangesim::app
