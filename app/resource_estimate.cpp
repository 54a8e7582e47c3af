#include "app/resource_estimate.h"

#include <cstdlib>
#include <filesystem>
#include <string>
#include <fmt/format.h>
#include <sys/statvfs.h>

#include "app/run_control.h"
#include "core/user_error.h"

namespace rangesim::app {

namespace {

// Free space of the file system that holds `dir`, or of its nearest existing parent.
double free_disk_bytes(const std::string& dir) {
  std::filesystem::path p = std::filesystem::absolute(dir);
  std::error_code ec;
  while (!p.empty() && !std::filesystem::exists(p, ec) && p != p.parent_path()) p = p.parent_path();
  struct statvfs st {};
  if (::statvfs(p.c_str(), &st) != 0) return -1;
  return static_cast<double>(st.f_bavail) * static_cast<double>(st.f_frsize);
}

}  // namespace

void check_resources(const std::string& command, const ResourceEstimate& e, const std::string& dir) {
  // The watchdog behind the estimates is tested by runs the estimates would refuse first.
  if (const char* skip = std::getenv("RANGESIM_SKIP_ESTIMATES"); skip && std::string(skip) == "1") return;
  const RunBudget& b = run_budget();
  const double limit =
      b.max_memory_bytes > 0 ? static_cast<double>(b.max_memory_bytes) : static_cast<double>(available_memory_bytes());
  if (limit > 0 && e.memory_bytes > limit)
    throw UserError(fmt::format("{}: needs about {} of memory ({}); allowed: {}; reduce {}", command,
                                bytes_text(e.memory_bytes), e.what,
                                b.max_memory_bytes > 0 ? fmt::format("--max-memory {}", b.max_memory_text)
                                                       : fmt::format("the {} available", bytes_text(limit)),
                                e.reduce));
  if (dir.empty() || e.disk_bytes <= 0) return;
  const double free = free_disk_bytes(dir);
  if (free >= 0 && e.disk_bytes > free)
    throw UserError(fmt::format("{}: the outputs need about {} in {} ({}); allowed: the {} free there; reduce {}",
                                command, bytes_text(e.disk_bytes), dir, e.what, bytes_text(free), e.reduce));
}

}  // namespace rangesim::app
