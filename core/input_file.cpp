#include "core/input_file.h"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <fmt/format.h>
#include <sys/stat.h>
#include <unistd.h>

#include "core/user_error.h"

namespace rangesim {

namespace {

std::string open_error(int err) {
  switch (err) {
    case ENOENT: return "no such file";
    case ENOTDIR: return "a component of the path is not a directory";
    case EACCES:
    case EPERM: return "permission denied";
    case ELOOP: return "too many levels of symbolic links (a symbolic-link loop)";
    case ENXIO: return "it is a socket or a device that cannot be opened";
    case ENAMETOOLONG: return "the name is too long";
    case EISDIR: return "it is a directory, not a regular file";
    default: return std::strerror(err);
  }
}

std::string type_error(mode_t mode) {
  if (S_ISREG(mode)) return "";
  if (S_ISDIR(mode)) return "it is a directory, not a regular file";
  if (S_ISFIFO(mode)) return "it is a FIFO (named pipe), not a regular file";
  if (S_ISCHR(mode)) return "it is a character device, not a regular file";
  if (S_ISBLK(mode)) return "it is a block device, not a regular file";
  if (S_ISSOCK(mode)) return "it is a socket, not a regular file";
  return "it is not a regular file";
}

// Opens `path` for reading without blocking on a FIFO; -1 and `reason` on failure.
int open_regular(const std::string& path, std::string& reason) {
  if (path.empty()) {
    reason = "the name is empty";
    return -1;
  }
  const int fd = ::open(path.c_str(), O_RDONLY | O_NONBLOCK | O_CLOEXEC | O_NOCTTY);
  if (fd < 0) {
    reason = open_error(errno);
    return -1;
  }
  struct stat st {};
  if (::fstat(fd, &st) != 0) {
    reason = std::strerror(errno);
  } else {
    reason = type_error(st.st_mode);
  }
  if (!reason.empty()) {
    ::close(fd);
    return -1;
  }
  return fd;
}

UserError refusal(const std::string& where, const std::string& what, const std::string& reason,
                  std::uintmax_t max_bytes) {
  return UserError(fmt::format("{}: cannot read {}: {}; allowed: a regular file of at most {} bytes", where, what,
                               reason, max_bytes));
}

}  // namespace

std::string unreadable_reason(const std::string& path) {
  std::string reason;
  const int fd = open_regular(path, reason);
  if (fd >= 0) ::close(fd);
  return reason;
}

void check_readable(const std::string& path, const std::string& what, std::uintmax_t max_bytes,
                    const std::string& where) {
  if (const std::string reason = unreadable_reason(path); !reason.empty())
    throw refusal(where.empty() ? path : where, what, reason, max_bytes);
}

std::string read_input_file(const std::string& path, const std::string& what, std::uintmax_t max_bytes,
                            const std::string& where) {
  const auto refuse = [&](const std::string& reason) {
    return refusal(where.empty() ? path : where, what, reason, max_bytes);
  };
  std::string reason;
  const int fd = open_regular(path, reason);
  if (fd < 0) throw refuse(reason);
  std::string text;
  char buffer[65536];
  for (;;) {
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) {
      const int err = errno;
      ::close(fd);
      throw refuse(fmt::format("read failed ({})", std::strerror(err)));
    }
    if (n == 0) break;
    // Checked while reading, not from st_size: a file can grow, and /proc files report size 0.
    if (text.size() + static_cast<std::size_t>(n) > max_bytes) {
      ::close(fd);
      throw refuse(fmt::format("it has more than {} bytes", max_bytes));
    }
    text.append(buffer, static_cast<std::size_t>(n));
  }
  ::close(fd);
  return text;
}

}  // namespace rangesim
