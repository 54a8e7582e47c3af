#include "app/file_replace.h"

#include <fcntl.h>
#include <sys/stat.h>

#include <cerrno>
#include <cstdio>
#include <filesystem>
#include <system_error>

namespace fs = std::filesystem;

namespace rangesim::app {

void replace_file(const std::string& from, const std::string& to) {
#if defined(RENAME_EXCHANGE)
  struct stat st {};
  // Only a regular file is exchanged: a directory of that name must make the move fail, as a
  // rename over it does, not land in the staging folder to be removed with it.
  if (::lstat(to.c_str(), &st) == 0 && S_ISREG(st.st_mode)) {
    if (::renameat2(AT_FDCWD, from.c_str(), AT_FDCWD, to.c_str(), RENAME_EXCHANGE) == 0) {
      std::error_code ec;
      fs::remove(from, ec);  // the old file; if this fails, a later run removes it as a dead run's staged file
      return;
    }
    if (errno != EINVAL && errno != ENOSYS && errno != ENOENT)
      throw fs::filesystem_error("cannot move the file into place", from, to,
                                 std::error_code(errno, std::generic_category()));
  }
#endif
  fs::rename(from, to);
}

}  // namespace rangesim::app
