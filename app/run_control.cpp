#include "app/run_control.h"

#include <cerrno>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstring>
#include <dirent.h>
#include <fcntl.h>
#include <fmt/format.h>
#include <fstream>
#include <limits>
#include <mutex>
#include <sys/syscall.h>
#include <thread>
#include <unistd.h>

namespace rangesim::app {

namespace {

using Clock = std::chrono::steady_clock;
const Clock::time_point g_start = Clock::now();

// The cleanup table is read by a signal handler: fixed storage, and a slot's state says whether
// its path may be read (2) or is being written (1).
constexpr int kSlots = 16;
constexpr std::size_t kPathMax = 4096;
enum class Removal { Path, Tree, Prefixed };  // register_cleanup, tree; register_prefix_cleanup
struct Slot {
  std::atomic<int> state{0};  // 0 free, 1 being changed, 2 ready
  Removal removal = Removal::Path;
  char path[kPathMax] = {};
};
Slot g_slots[kSlots];

std::atomic<int> g_guards{0};       // live StopGuards
std::atomic<int> g_committing{0};   // live CommitSections
std::atomic<int> g_pending{0};      // exit code of a stop deferred by a commit (0: none)
std::atomic<bool> g_flag{false};    // stop_flag()
std::atomic<int> g_code{0};         // exit code of the stop
std::atomic<int> g_signal{0};       // the signal that stopped the run (0: a budget)
std::atomic<bool> g_ending{false};  // the run is being ended: only one thread does it
std::mutex g_reason_mutex;
std::string g_budget_reason;  // what ran out (under g_reason_mutex)
RunBudget g_budget;
std::uint64_t g_memory_limit = 0;  // --max-memory, or 90% of the memory available at the start
std::string g_command_line = "rangesim";

void write_all(const char* text) {
  for (std::size_t left = std::strlen(text); left > 0;) {
    const ssize_t n = ::write(STDERR_FILENO, text, left);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return;
    text += n, left -= static_cast<std::size_t>(n);
  }
}

// Removes `path` and what it holds, with async-signal-safe calls only; folders nest at most a few
// levels in a staging folder. With `only` (at depth 0), only the entries of folder `path` whose
// names start with it go, and the folder stays.
void remove_tree(const char* path, int depth, const char* only = nullptr) {
  static char names[8][kPathMax];
  alignas(8) static char buffers[8][8192];
  const int fd = ::open(path, O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
  if (fd < 0) {
    if (!only) ::unlink(path);
    return;
  }
  for (;;) {
    const long n = ::syscall(SYS_getdents64, fd, buffers[depth], sizeof buffers[depth]);
    if (n <= 0) break;
    for (long at = 0; at < n;) {
      const auto* e = reinterpret_cast<const struct dirent64*>(buffers[depth] + at);
      at += e->d_reclen;
      if (std::strcmp(e->d_name, ".") == 0 || std::strcmp(e->d_name, "..") == 0) continue;
      if (only && std::strncmp(e->d_name, only, std::strlen(only)) != 0) continue;
      if (::unlinkat(fd, e->d_name, 0) == 0 || depth + 1 >= 8) continue;
      const std::size_t a = std::strlen(path), b = std::strlen(e->d_name);
      if (a + b + 2 > kPathMax) continue;
      std::memcpy(names[depth], path, a);
      names[depth][a] = '/';
      std::memcpy(names[depth] + a + 1, e->d_name, b + 1);
      remove_tree(names[depth], depth + 1);
    }
  }
  ::close(fd);
  if (!only) ::rmdir(path);
}

// The entries of folder D named P... for a slot's "D/P" (register_prefix_cleanup).
void remove_prefixed(char* folder_and_prefix) {
  char* slash = std::strrchr(folder_and_prefix, '/');
  if (!slash) return;
  *slash = '\0';
  remove_tree(folder_and_prefix[0] ? folder_and_prefix : "/", 0, slash + 1);
  *slash = '/';
}

// Ends the run now: cleanup in reverse order of registration, the message, the exit code.
[[noreturn]] void end_now(int code, const char* message) {
  if (g_ending.exchange(true))
    for (;;) ::pause();  // another thread is ending the run
  for (int i = kSlots - 1; i >= 0; --i) {
    if (g_slots[i].state.load() != 2) continue;
    if (g_slots[i].removal == Removal::Tree)
      remove_tree(g_slots[i].path, 0);
    else if (g_slots[i].removal == Removal::Prefixed)
      remove_prefixed(g_slots[i].path);
    else if (::unlink(g_slots[i].path) != 0)
      ::rmdir(g_slots[i].path);
  }
  write_all(message);
  ::_exit(code);
}

const char* signal_message(int sig) {
  switch (sig) {
    case SIGINT: return "\nrangesim: interrupted (SIGINT, Ctrl-C); temporary files removed, nothing written\n";
    case SIGTERM: return "\nrangesim: stopped by SIGTERM; temporary files removed, nothing written\n";
    case SIGHUP:
      return "\nrangesim: stopped by SIGHUP (the terminal closed); temporary files removed, nothing written\n";
    default: return "\nrangesim: stopped by a signal; temporary files removed, nothing written\n";
  }
}

extern "C" void on_stop_signal(int sig) {
  const int saved = errno;
  g_signal.store(sig);
  if (g_guards.load() > 0) {
    g_code.store(128 + sig);
    g_flag.store(true);
  } else if (g_committing.load() > 0) {
    g_pending.store(128 + sig);
  } else {
    end_now(128 + sig, signal_message(sig));
  }
  errno = saved;
}

// A budget ran out (from the watch thread): a guarded sweep stops between points; any other run
// ends at once, unless its outputs are being committed (the run is then as good as done).
void budget_ran_out(const std::string& reason) {
  {
    std::lock_guard<std::mutex> lock(g_reason_mutex);
    if (!g_budget_reason.empty()) return;
    g_budget_reason = reason;
  }
  if (g_guards.load() > 0) {
    g_code.store(kExitBudget);
    g_flag.store(true);
    return;
  }
  if (g_committing.load() > 0) return;
  static std::string message;
  message = fmt::format("\nrangesim: {}; temporary files removed, nothing written\n", reason);
  end_now(kExitBudget, message.c_str());
}

void watch_budget() {
  for (;;) {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    const double t = seconds_since_start();
    if (g_memory_limit > 0) {
      const std::uint64_t rss = resident_bytes();
      if (rss > g_memory_limit) {
        const std::string limit = g_budget.max_memory_bytes > 0
                                      ? fmt::format("--max-memory {}", g_budget.max_memory_text)
                                      : fmt::format("90% of the memory available at the start ({}; --max-memory)",
                                                    bytes_text(static_cast<double>(g_memory_limit)));
        budget_ran_out(
            fmt::format("{} exceeded: {} resident after {:.1f} s; reduce the work (grid points, trials, "
                        "variants, frames, pixels)",
                        limit, bytes_text(static_cast<double>(rss)), t));
      }
    }
    if (g_budget.max_seconds > 0 && t > g_budget.max_seconds && g_guards.load() == 0)
      budget_ran_out(
          fmt::format("--max-seconds {} exceeded after {:.1f} s; raise it or reduce the work (grid "
                      "points, trials, variants, frames)",
                      g_budget.max_seconds_text, t));
  }
}

}  // namespace

void install_stop_handlers() {
  struct sigaction sa {};
  sa.sa_handler = on_stop_signal;
  sigemptyset(&sa.sa_mask);
  sa.sa_flags = SA_RESTART;
  // A signal the caller ignores stays ignored (nohup, a background job of a script).
  for (int sig : {SIGINT, SIGTERM, SIGHUP}) {
    struct sigaction old {};
    if (::sigaction(sig, nullptr, &old) == 0 && old.sa_handler == SIG_IGN) continue;
    ::sigaction(sig, &sa, nullptr);
  }
}

namespace {

int register_removal(const std::string& path, Removal removal) {
  if (path.size() + 1 > kPathMax) return -1;
  for (int i = 0; i < kSlots; ++i) {
    int expected = 0;
    if (!g_slots[i].state.compare_exchange_strong(expected, 1)) continue;
    g_slots[i].removal = removal;
    std::memcpy(g_slots[i].path, path.c_str(), path.size() + 1);
    g_slots[i].state.store(2);
    return i;
  }
  return -1;
}

}  // namespace

int register_cleanup(const std::string& path, bool tree) {
  return register_removal(path, tree ? Removal::Tree : Removal::Path);
}

int register_prefix_cleanup(const std::string& folder_and_prefix) {
  return register_removal(folder_and_prefix, Removal::Prefixed);
}

void unregister_cleanup(int slot) {
  if (slot >= 0 && slot < kSlots) g_slots[slot].state.store(0);
}

CommitSection::CommitSection() { ++g_committing; }

CommitSection::~CommitSection() {
  if (--g_committing > 0) return;
  if (const int code = g_pending.exchange(0); code != 0)
    end_now(code, "\nrangesim: stopped by a signal after the outputs were complete\n");
}

StopGuard::StopGuard() {
  g_flag = false;
  ++g_guards;
}

StopGuard::~StopGuard() { --g_guards; }

std::atomic<bool>& stop_flag() { return g_flag; }

int stop_exit_code() { return g_code.load() != 0 ? g_code.load() : 130; }

std::string stop_reason() {
  {
    std::lock_guard<std::mutex> lock(g_reason_mutex);
    if (g_code.load() == kExitBudget && !g_budget_reason.empty()) return g_budget_reason;
  }
  switch (g_signal.load()) {
    case SIGTERM: return "stopped by SIGTERM";
    case SIGHUP: return "stopped by SIGHUP";
    default: return "interrupted";
  }
}

void start_budget(const RunBudget& budget) {
  g_budget = budget;
  g_memory_limit = budget.max_memory_bytes;
  if (g_memory_limit == 0) g_memory_limit = available_memory_bytes() / 10 * 9;
  if (budget.max_seconds > 0 || g_memory_limit > 0) std::thread(watch_budget).detach();
}

const RunBudget& run_budget() { return g_budget; }

void end_run_over_budget(const std::string& message) {
  static std::string text;
  text = "\nrangesim: " + message + "; temporary files removed, nothing written\n";
  end_now(kExitBudget, text.c_str());
}

double seconds_since_start() { return std::chrono::duration<double>(Clock::now() - g_start).count(); }

double time_budget_left() {
  if (g_budget.max_seconds <= 0) return std::numeric_limits<double>::infinity();
  return g_budget.max_seconds - seconds_since_start();
}

std::uint64_t available_memory_bytes() {
  std::ifstream in("/proc/meminfo");
  std::string key, unit;
  std::uint64_t kib = 0;
  while (in >> key >> kib >> unit)
    if (key == "MemAvailable:") return kib * 1024;
  return 0;
}

std::uint64_t resident_bytes() {
  const int fd = ::open("/proc/self/statm", O_RDONLY | O_CLOEXEC);
  if (fd < 0) return 0;
  char text[128] = {};
  const ssize_t n = ::read(fd, text, sizeof text - 1);
  ::close(fd);
  unsigned long long size = 0, resident = 0;
  if (n <= 0 || std::sscanf(text, "%llu %llu", &size, &resident) != 2) return 0;
  return resident * static_cast<std::uint64_t>(::sysconf(_SC_PAGESIZE));
}

std::string bytes_text(double bytes) {
  const char* units[] = {"B", "KiB", "MiB", "GiB", "TiB"};
  int u = 0;
  while (bytes >= 1024 && u < 4) bytes /= 1024, ++u;
  return fmt::format(u == 0 ? "{:.0f} {}" : "{:.3g} {}", bytes, units[u]);
}

void set_command_line(int argc, const char* const* argv) {
  std::string c = "rangesim";
  for (int i = 1; i < argc; ++i) c += " " + shell_quote(argv[i]);
  g_command_line = c;
}

const std::string& command_line() { return g_command_line; }

std::string shell_quote(const std::string& s) {
  if (!s.empty() && s.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789-_./:=+,") ==
                        std::string::npos)
    return s;
  std::string r = "'";
  for (char c : s) r += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return r + "'";
}

}  // namespace rangesim::app
