#include "app/simulate/trace_output.h"

#include <cstdio>
#include <cstdlib>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <fmt/format.h>
#include <spawn.h>
#include <stdexcept>
#include <sys/wait.h>
#include <unistd.h>
#include <vector>

#include "app/output_dir.h"
#include "app/run_control.h"
#include "core/user_error.h"

extern char** environ;

namespace rangesim::app {

namespace {

namespace fs = std::filesystem;

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() > tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

// Runs argv[0] (searched on PATH) with stdout/stderr sent to /dev/null; returns the exit status
// or -1 when it could not be started.
int run_quiet(const std::vector<std::string>& args) {
  std::vector<char*> argv;
  for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  posix_spawn_file_actions_t fa;
  posix_spawn_file_actions_init(&fa);
  posix_spawn_file_actions_addopen(&fa, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&fa, 2, "/dev/null", O_WRONLY, 0);
  pid_t pid = 0;
  const int rc = posix_spawnp(&pid, argv[0], &fa, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&fa);
  if (rc != 0) return -1;
  int status = 0;
  if (waitpid(pid, &status, 0) < 0) return -1;
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

bool on_path(const std::string& tool) {
  const char* path = std::getenv("PATH");
  std::string dirs = path ? path : "/usr/bin:/bin";
  std::size_t start = 0;
  while (start <= dirs.size()) {
    const std::size_t end = dirs.find(':', start);
    const std::string dir = dirs.substr(start, end == std::string::npos ? std::string::npos : end - start);
    if (!dir.empty() && ::access((fs::path(dir) / tool).c_str(), X_OK) == 0) return true;
    if (end == std::string::npos) break;
    start = end + 1;
  }
  return false;
}

}  // namespace

TraceOutput::TraceOutput(const std::string& path, bool kernel_only) : path_(path) {
  if (path_.empty()) return;
  if (kernel_only)
    throw UserError("--trace needs the SystemC model; drop --kernel-only (the bare kernels have no waveform)");
  if (!ends_with(path_, ".vcd") && !ends_with(path_, ".fst"))
    throw UserError(fmt::format("--trace {}: the waveform file name must end in .vcd or .fst", path_));
  check_output_file(path_, "--trace");
  const fs::path parent = fs::absolute(path_).parent_path();
  std::error_code ec;
  for (fs::path p = parent; !p.empty() && !fs::exists(p, ec) && p != p.parent_path(); p = p.parent_path())
    made_root_ = p.string();
  fs::create_directories(parent, ec);  // like --out: the trace's folder is made
  if (!fs::is_directory(parent) || ::access(parent.c_str(), W_OK) != 0)
    throw UserError(fmt::format("--trace {}: cannot create or write to the folder {}", path_, parent.string()));
  if (ends_with(path_, ".fst") && !on_path("vcd2fst"))
    throw UserError(
        fmt::format("--trace {}: writing FST needs vcd2fst (Debian package gtkwave, scripts/install-deps.sh); "
                    "or name the trace .vcd",
                    path_));
  // The model writes <stem>.vcd, <stem>.gtkw and its filters into a staging folder beside the
  // target, under their final names (the save file refers to them by name); commit() moves them.
  const fs::path target = fs::absolute(path_);
  stem_ = target.stem().string();
  staging_ = (target.parent_path() / fmt::format(".{}.partial-{}", stem_, ::getpid())).string();
  fs::create_directories(staging_);
  staging_slot_ = register_cleanup(staging_, true);  // a signal removes it too
  vcd_base_ = (fs::path(staging_) / stem_).string();
}

TraceOutput::~TraceOutput() {
  unregister_cleanup(staging_slot_);
  if (path_.empty()) return;
  std::error_code ec;
  fs::remove_all(staging_, ec);
  if (committed_ || made_root_.empty()) return;
  // The folders made for the trace, innermost first; one that holds anything stays.
  for (fs::path p = fs::absolute(path_).parent_path(); fs::remove(p, ec) && p.string() != made_root_;)
    p = p.parent_path();
}

void TraceOutput::finish() {
  if (path_.empty()) return;
  const std::string vcd = vcd_base_ + ".vcd";
  if (!fs::exists(vcd)) throw std::runtime_error(fmt::format("--trace {}: the model wrote no waveform", path_));
  if (ends_with(path_, ".vcd")) {
    finished_ = vcd;
    return;
  }
  finished_ = vcd_base_ + ".fst";
  const int rc = run_quiet({"vcd2fst", vcd, finished_});
  std::error_code ec;
  fs::remove(vcd, ec);
  if (rc != 0 || !fs::exists(finished_)) {
    fs::remove(finished_, ec);
    throw std::runtime_error(fmt::format("--trace {}: vcd2fst failed (exit {}); nothing written", path_, rc));
  }
  // The save file names the dump it opens.
  const std::string gtkw = vcd_base_ + ".gtkw";
  if (fs::exists(gtkw)) {
    std::ifstream in(gtkw);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::string from = "[dumpfile] \"" + stem_ + ".vcd\"", to = "[dumpfile] \"" + stem_ + ".fst\"";
    if (const std::size_t at = text.find(from); at != std::string::npos) text.replace(at, from.size(), to);
    std::ofstream(gtkw) << text;
  }
}

std::string TraceOutput::commit() {
  if (path_.empty()) return "";
  if (finished_.empty()) throw std::logic_error("TraceOutput::commit before finish");
  // The save file and filters first, the trace last: a present trace means a complete set.
  const fs::path dir = fs::absolute(path_).parent_path();
  for (const auto& e : fs::directory_iterator(staging_))
    if (e.path() != fs::path(finished_)) fs::rename(e.path(), dir / e.path().filename());
  fs::rename(finished_, path_);
  std::error_code ec;
  fs::remove_all(staging_, ec);
  committed_ = true;
  return path_;
}

}  // namespace rangesim::app
