#include "app/output_dir.h"

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <unistd.h>

#include "app/file_replace.h"
#include "app/output_lock.h"
#include "app/run_control.h"
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

void remove_stale_staging(const std::string& dir) {
  std::error_code ec;
  for (const auto& e : fs::directory_iterator(dir, ec)) {
    const std::string name = e.path().filename().string();
    if (name.rfind(".staging-", 0) != 0) continue;  // .staging-sweep (a sweep's journal) has no pid
    const std::string digits = name.substr(9, name.find('.', 9) - 9);
    if (digits.empty() || digits.size() > 9 || digits.find_first_not_of("0123456789") != std::string::npos) continue;
    const long pid = std::stol(digits);
    if (pid != ::getpid() && ::kill(static_cast<pid_t>(pid), 0) != 0 && errno == ESRCH) fs::remove_all(e.path(), ec);
  }
}

OutputDir::OutputDir(const std::string& dir, const std::string& flag, const OutputFolder& folder)
    : dir_(dir), folder_(folder) {
  std::error_code ec;
  const fs::file_status st = fs::status(dir_, ec);
  if (ec && ec != std::errc::no_such_file_or_directory)
    throw UserError(fmt::format("{} {}: cannot use it as an output directory ({})", flag, dir_, ec.message()));
  if (fs::exists(st) && !fs::is_directory(st))
    throw UserError(fmt::format("{} {}: exists and is not a directory", flag, dir_));
  if (!fs::exists(st)) {
    fs::create_directories(dir_, ec);
    if (ec) throw UserError(fmt::format("{} {}: cannot create output directory ({})", flag, dir_, ec.message()));
    created_dir_ = true;
    dir_slot_ = register_cleanup(dir_, false);  // removed by an ended run only if empty
  }
  try {
    if (::access(dir_.c_str(), W_OK) != 0)
      throw UserError(fmt::format("{} {}: output directory is not writable", flag, dir_));
    if (!folder_.kind.empty() && folder_.lock) lock_ = std::make_unique<OutputLock>(dir_, flag);
    remove_stale_staging(dir_);
    if (!folder_.kind.empty() && folder_.lock) previous_ = read_manifest(dir_);
    if (previous_ && previous_->kind != folder_.kind && !folder_.force)
      throw UserError(
          fmt::format("{} {}: holds the results of another command ({} files of `rangesim {}`); add --force to "
                      "replace them (files that are not rangesim's stay), or choose another {}",
                      flag, dir_, previous_->files.size(), previous_->kind, flag));
    // A folder written before manifests existed: its files cannot be told from the user's, so a
    // run would leave the old ones it does not write again beside its own.
    if (!folder_.kind.empty() && folder_.lock && !previous_ && !folder_.force &&
        fs::exists(fs::path(dir_) / "summary.json"))
      throw UserError(fmt::format(
          "{} {}: holds an earlier rangesim run without a record of its files (summary.json, no {}); add --force "
          "to write into it anyway (files of the same names are replaced, the others stay), or choose another {}",
          flag, dir_, kManifestName, flag));
    // Staged files beside their final names, not in a folder of their own: the folder's removal
    // at the commit waited 0.2 ms for the disk's discard of its block on an ext4 without a journal
    // mounted with `discard` (a model of the commit of a `simulate` run's files: 0.33 against 0.52 to
    // 0.56 ms, medians of 40 alternating runs, measured).
    staging_ = (fs::path(dir_) / fmt::format(".staging-{}", ::getpid())).string();
    if (folder_.same_names) {
      make_staging();
      prefix_ = staging_ + "/";
    } else {
      prefix_ = staging_ + ".";
      prefix_slot_ = register_prefix_cleanup(prefix_);
    }
  } catch (...) {
    lock_.reset();
    unregister_cleanup(dir_slot_);
    if (created_dir_) fs::remove(dir_, ec);
    throw;
  }
}

OutputDir::~OutputDir() {
  std::error_code ec;
  if (!committed_) {
    if (!folder_.same_names) remove_staged();
    if (made_staging_) fs::remove_all(staging_, ec);
  }
  unregister_cleanup(staging_slot_);
  unregister_cleanup(prefix_slot_);
  lock_.reset();  // its file goes first, so that a folder this run created can go too
  unregister_cleanup(dir_slot_);
  if (!committed_ && created_dir_ && fs::is_empty(dir_, ec)) fs::remove(dir_, ec);
}

void OutputDir::remove_staged() const {
  std::error_code ec;
  const std::string own = fs::path(prefix_).filename().string();
  for (const auto& e : fs::directory_iterator(dir_, ec)) {
    const std::string name = e.path().filename().string();
    std::error_code remove_ec;
    if (name.rfind(own, 0) == 0) fs::remove_all(e.path(), remove_ec);
  }
}

std::string OutputDir::staged(const std::string& name) {
  names_.push_back(name);
  return prefix_ + name;
}

void OutputDir::make_staging() {
  if (made_staging_) return;
  std::error_code ec;
  fs::create_directory(staging_, ec);
  if (ec) throw UserError(fmt::format("{}: cannot make the staging folder ({})", staging_, ec.message()));
  made_staging_ = true;
  staging_slot_ = register_cleanup(staging_, true);
}

std::string OutputDir::scratch(const std::string& name) {
  make_staging();
  return (fs::path(staging_) / name).string();
}

void OutputDir::write(const std::string& name, const std::string& text) {
  const std::string path = staged(name);
  std::ofstream out(path, std::ios::binary);
  out << text;
  out.close();
  if (!out) throw std::runtime_error(fmt::format("cannot write {}", path));
}

std::vector<std::string> OutputDir::commit() {
  const CommitSection section;  // a signal now waits until the folder is complete
  std::vector<std::string> names;
  for (const auto& name : names_)
    if (fs::exists(prefix_ + name) && std::find(names.begin(), names.end(), name) == names.end())
      names.push_back(name);  // optional outputs (plots without gnuplot) may be missing
  // A directory where a file goes would stop the moves half-way (a rename cannot replace it):
  // refused before anything moves, so the folder keeps the previous run's files.
  for (const auto& name : names) {
    std::error_code ec;
    if (fs::is_directory(fs::symlink_status(fs::path(dir_) / name, ec)))
      throw UserError(
          fmt::format("{}: is a directory where this run writes its file {}; allowed: a regular file "
                      "(which is replaced) or nothing. Move it, or choose another output folder",
                      (fs::path(dir_) / name).string(), name));
  }
  // A rerun writing the files the previous run listed finds its manifest already true: neither
  // write below would change it (they were 0.2 to 0.25 ms of a `simulate` commit, measured).
  const bool manifest = !folder_.kind.empty() && folder_.lock &&
                        !(previous_ && previous_->kind == folder_.kind && previous_->files == names);
  std::vector<std::string> stale;
  if (previous_)
    for (const auto& f : previous_->files)
      if (std::find(names.begin(), names.end(), f) == names.end()) stale.push_back(f);
  // While files move, the manifest lists the old and the new ones: a kill at any point leaves no
  // rangesim file the next run does not know about.
  if (manifest) {
    std::vector<std::string> both = names;
    both.insert(both.end(), stale.begin(), stale.end());
    write_manifest(dir_, {folder_.kind, both}, prefix_);
  }
  std::vector<std::string> written;
  for (const auto& name : names) {
    const fs::path to = fs::path(dir_) / name;
    replace_file(prefix_ + name, to.string());
    written.push_back(to.string());
  }
  std::error_code ec;
  for (const auto& f : stale)
    if (fs::is_regular_file(fs::symlink_status(fs::path(dir_) / f, ec))) fs::remove(fs::path(dir_) / f, ec);
  if (manifest) write_manifest(dir_, {folder_.kind, names}, prefix_);
  if (made_staging_) fs::remove_all(staging_, ec);
  committed_ = true;
  return written;
}

}  // namespace rangesim::app
