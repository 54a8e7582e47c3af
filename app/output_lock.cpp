#include "app/output_lock.h"

#include <cerrno>
#include <cstring>
#include <ctime>
#include <fcntl.h>
#include <fmt/format.h>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

#include "app/run_control.h"
#include "core/user_error.h"

namespace rangesim::app {

namespace {

constexpr const char* kLockName = ".rangesim.lock";

std::string read_holder(int fd) {
  char text[2048] = {};
  const ssize_t n = ::pread(fd, text, sizeof text - 1, 0);
  std::string s = n > 0 ? std::string(text, static_cast<std::size_t>(n)) : std::string();
  for (auto& c : s)
    if (c == '\n') c = ';';
  while (!s.empty() && (s.back() == ';' || s.back() == ' ')) s.pop_back();
  return s.empty() ? "a rangesim run that has just started" : s;
}

}  // namespace

OutputLock::OutputLock(const std::string& dir, const std::string& flag) : path_(dir + "/" + kLockName) {
  // The holder removes the file before it lets go: a lock taken on a file that was meanwhile
  // removed (or replaced) is no lock, so retry on the file now at the path.
  for (int attempt = 0; attempt < 100; ++attempt) {
    const int fd = ::open(path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0644);
    if (fd < 0)
      throw UserError(fmt::format("{} {}: cannot create the lock file {} ({}); allowed: a writable folder", flag, dir,
                                  kLockName, std::strerror(errno)));
    if (::flock(fd, LOCK_EX | LOCK_NB) != 0) {
      const std::string holder = read_holder(fd);
      ::close(fd);
      throw UserError(
          fmt::format("{} {}: another rangesim run is writing there ({}); wait for it to end, or "
                      "choose another {}",
                      flag, dir, holder, flag));
    }
    struct stat held {
    }, now{};
    if (::fstat(fd, &held) == 0 && ::stat(path_.c_str(), &now) == 0 && held.st_ino == now.st_ino &&
        held.st_dev == now.st_dev) {
      fd_ = fd;
      break;
    }
    ::close(fd);
  }
  if (fd_ < 0) throw UserError(fmt::format("{} {}: cannot take the lock {}", flag, dir, kLockName));
  const std::time_t t = std::time(nullptr);
  char when[32] = {};
  std::strftime(when, sizeof when, "%Y-%m-%d %H:%M:%S", std::localtime(&t));
  const std::string text = fmt::format("pid {}, started {}: {}\n", ::getpid(), when, command_line());
  // The note is for messages only: the lock holds without it. Written, then cut to its length (a
  // stale lock file may hold a longer one): a cut to zero makes ext4 write the file's block out
  // when it is closed (its auto_da_alloc), which the removal at the end then waits for, and frees.
  if (::pwrite(fd_, text.data(), text.size(), 0) == static_cast<ssize_t>(text.size()))
    (void)!::ftruncate(fd_, static_cast<off_t>(text.size()));
  cleanup_slot_ = register_cleanup(path_, false);
}

OutputLock::~OutputLock() {
  unregister_cleanup(cleanup_slot_);
  ::unlink(path_.c_str());
  ::close(fd_);
}

}  // namespace rangesim::app
