#include "app/sweep_journal.h"

#include <cerrno>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <sys/stat.h>
#include <unistd.h>
#include <vector>

#include "core/user_error.h"

namespace rangesim::app {

namespace {

constexpr const char* kMagic = "rangesim-sweep-journal 1";

std::string escape(const std::string& s) {
  std::string r;
  for (char c : s) {
    if (c == '\\')
      r += "\\\\";
    else if (c == '\n')
      r += "\\n";
    else
      r += c;
  }
  return r;
}

std::vector<std::string> lines_of(const std::string& s) {
  std::vector<std::string> out;
  std::istringstream in(s);
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

std::string unescape(const std::string& s) {
  std::string r;
  for (size_t i = 0; i < s.size(); ++i) {
    if (s[i] == '\\' && i + 1 < s.size()) {
      r += s[i + 1] == 'n' ? '\n' : s[i + 1];
      ++i;
    } else {
      r += s[i];
    }
  }
  return r;
}

// Writes all of `text` with one write() where the kernel allows (a regular file: always), then
// makes it durable.
void write_durable(int fd, const std::string& text, const std::string& path) {
  size_t off = 0;
  while (off < text.size()) {
    const ssize_t n = ::write(fd, text.data() + off, text.size() - off);
    if (n < 0) {
      if (errno == EINTR) continue;
      throw std::runtime_error(fmt::format("journal {}: write failed ({})", path, std::strerror(errno)));
    }
    off += static_cast<size_t>(n);
  }
  if (::fsync(fd) != 0)
    throw std::runtime_error(fmt::format("journal {}: fsync failed ({})", path, std::strerror(errno)));
}

std::string record_line(long long index, const std::string& payload) {
  const std::uint64_t h = SweepJournal::hash(fmt::format("{} {}", index, payload));
  return fmt::format("P {} {} {} {:016x}\n", index, payload.size(), payload, h);
}

}  // namespace

std::uint64_t SweepJournal::hash(const std::string& text) {
  std::uint64_t h = 0xcbf29ce484222325ULL;
  for (unsigned char c : text) h = (h ^ c) * 0x100000001b3ULL;
  return h;
}

SweepJournal::SweepJournal(const std::string& path, const std::string& fingerprint, bool resume,
                           const std::string& resume_flag)
    : path_(path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const bool exists = fs::exists(path_, ec);
  const std::string header = fmt::format("{} {:016x}\n{}\n", kMagic, hash(fingerprint), escape(fingerprint));
  if (exists && !resume)
    throw UserError(fmt::format(
        "{}: the journal of an unfinished sweep is there; add {} to continue it, or delete the file to start over",
        path_, resume_flag));
  long long good_bytes = 0;
  if (exists) {
    std::ifstream in(path_, std::ios::binary);
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const size_t h1 = text.find('\n');
    const size_t h2 = h1 == std::string::npos ? std::string::npos : text.find('\n', h1 + 1);
    if (h2 == std::string::npos || text.compare(0, std::strlen(kMagic), kMagic) != 0)
      throw UserError(fmt::format("{}: not a rangesim sweep journal (delete it to start over)", path_));
    if (text.compare(0, h2 + 1, header) != 0) {
      const std::vector<std::string> was = lines_of(unescape(text.substr(h1 + 1, h2 - h1 - 1)));
      const std::vector<std::string> now = lines_of(fingerprint);
      std::string diff = "(header differs)";
      for (size_t i = 0; i < std::max(was.size(), now.size()); ++i) {
        const std::string a = i < was.size() ? was[i] : "(none)", b = i < now.size() ? now[i] : "(none)";
        if (a != b) {
          diff = fmt::format("journal has `{}`, this run has `{}`", a, b);
          break;
        }
      }
      throw UserError(
          fmt::format("{}: --resume refused: the journal belongs to a sweep with a different preset or options: {}. "
                      "Rerun with the original options, or delete the journal to start over",
                      path_, diff));
    }
    good_bytes = static_cast<long long>(h2 + 1);
    size_t pos = h2 + 1;
    while (pos < text.size()) {
      const size_t end = text.find('\n', pos);
      if (end == std::string::npos) break;  // torn last record
      const std::string line = text.substr(pos, end - pos);
      long long index = 0;
      size_t len = 0;
      int consumed = 0;
      if (std::sscanf(line.c_str(), "P %lld %zu %n", &index, &len, &consumed) < 2 || consumed <= 0 ||
          static_cast<size_t>(consumed) + len + 17 != line.size())
        break;
      const std::string payload = line.substr(static_cast<size_t>(consumed), len);
      if (line.substr(static_cast<size_t>(consumed) + len) !=
          fmt::format(" {:016x}", hash(fmt::format("{} {}", index, payload))))
        break;
      done_[index] = payload;
      pos = end + 1;
      good_bytes = static_cast<long long>(pos);
    }
  }
  fs::create_directories(fs::path(path_).parent_path(), ec);
  fd_ = ::open(path_.c_str(), O_WRONLY | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0) throw UserError(fmt::format("{}: cannot open the sweep journal ({})", path_, std::strerror(errno)));
  if (!exists) {
    write_durable(fd_, header, path_);
  } else {
    // Drop a torn tail, then append after the last good record.
    if (::ftruncate(fd_, good_bytes) != 0 || ::lseek(fd_, 0, SEEK_END) < 0)
      throw std::runtime_error(fmt::format("journal {}: cannot truncate ({})", path_, std::strerror(errno)));
  }
  // Make the new file's directory entry durable too.
  const int dfd = ::open(fs::path(path_).parent_path().c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dfd >= 0) {
    ::fsync(dfd);
    ::close(dfd);
  }
}

SweepJournal::~SweepJournal() {
  if (fd_ >= 0) ::close(fd_);
}

void SweepJournal::append(long long index, const std::string& payload) {
  if (payload.find('\n') != std::string::npos) throw std::logic_error("journal payload with a newline");
  const std::string line = record_line(index, payload);
  std::lock_guard<std::mutex> lock(mutex_);
  if (fd_ < 0) throw std::logic_error("journal already removed");
  write_durable(fd_, line, path_);
}

void SweepJournal::remove() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  std::error_code ec;
  std::filesystem::remove(path_, ec);
}

}  // namespace rangesim::app
