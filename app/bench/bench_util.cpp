#include "app/bench/bench_util.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <spawn.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <stdexcept>

#include "core/user_error.h"

namespace rangesim::app::bench {

namespace {
Clock::time_point g_start = Clock::now();
}  // namespace

void set_progress_start(Clock::time_point t0) { g_start = t0; }

double cpu_now() {
  timespec ts{};
  ::clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return static_cast<double>(ts.tv_sec) + 1e-9 * static_cast<double>(ts.tv_nsec);
}

double children_cpu_now() {
  rusage u{};
  ::getrusage(RUSAGE_CHILDREN, &u);
  auto s = [](const timeval& t) { return static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_usec); };
  return s(u.ru_utime) + s(u.ru_stime);
}

void progress(const std::string& what) {
  fmt::print(stderr, "bench [{:6.1f} s] {}\n", seconds_since(g_start), what);
  std::fflush(stderr);
}

nlohmann::json run_in_child(const std::function<nlohmann::json()>& job) {
  int fd[2];
  if (::pipe(fd) != 0) throw std::runtime_error("bench: pipe() failed");
  std::fflush(stdout);
  std::fflush(stderr);
  const pid_t pid = ::fork();
  if (pid < 0) throw std::runtime_error("bench: fork() failed");
  if (pid == 0) {
    ::close(fd[0]);
    ::dup2(2, 1);  // SystemC's own messages ("simulation stopped by user") must not reach our stdout (--json)
    std::string text;
    try {
      text = job().dump();
    } catch (const std::exception& e) {
      text = nlohmann::json{{"error", e.what()}}.dump();
    } catch (...) {
      text = nlohmann::json{{"error", "unknown exception"}}.dump();
    }
    std::size_t done = 0;
    while (done < text.size()) {
      const ssize_t n = ::write(fd[1], text.data() + done, text.size() - done);
      if (n <= 0) break;
      done += static_cast<std::size_t>(n);
    }
    ::close(fd[1]);
    std::fflush(stdout);
    std::fflush(stderr);
    ::_exit(0);  // no static destructors: SystemC's would run on a half-finished simulation
  }
  ::close(fd[1]);
  std::string text;
  char buf[65536];
  for (;;) {
    const ssize_t n = ::read(fd[0], buf, sizeof buf);
    if (n <= 0) break;
    text.append(buf, static_cast<std::size_t>(n));
  }
  ::close(fd[0]);
  int status = 0;
  ::waitpid(pid, &status, 0);
  if (text.empty()) return nlohmann::json{{"error", fmt::format("child ended with status {}", status)}};
  return nlohmann::json::parse(text);
}

SelfRun run_self_timed(const std::vector<std::string>& args) {
  std::vector<std::string> argv_text = {"rangesim"};
  argv_text.insert(argv_text.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& a : argv_text) argv.push_back(a.data());
  argv.push_back(nullptr);
  int fd[2];
  if (::pipe(fd) != 0) throw std::runtime_error("bench: pipe() failed");
  // posix_spawn, not fork: the child starts without a copy of this (large) process's page tables,
  // whose teardown at exec would count as the child's own time.
  posix_spawn_file_actions_t files;
  posix_spawn_file_actions_init(&files);
  posix_spawn_file_actions_adddup2(&files, fd[1], 1);
  posix_spawn_file_actions_addclose(&files, fd[0]);
  posix_spawn_file_actions_addclose(&files, fd[1]);
  posix_spawn_file_actions_addopen(&files, 2, "/dev/null", O_WRONLY, 0);
  std::fflush(stdout);
  std::fflush(stderr);
  const auto t0 = Clock::now();
  pid_t pid = 0;
  const int spawned = ::posix_spawn(&pid, "/proc/self/exe", &files, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&files);
  ::close(fd[1]);
  if (spawned != 0) {
    ::close(fd[0]);
    throw std::runtime_error(std::string("bench: cannot start rangesim: ") + std::strerror(spawned));
  }
  SelfRun r;
  char buf[65536];
  for (ssize_t n; (n = ::read(fd[0], buf, sizeof buf)) != 0;) {
    if (n < 0 && errno == EINTR) continue;
    if (n < 0) break;
    r.out.append(buf, static_cast<std::size_t>(n));
  }
  ::close(fd[0]);
  int status = 0;
  rusage u{};
  while (::wait4(pid, &status, 0, &u) < 0 && errno == EINTR) {
  }
  r.wall_s = seconds_since(t0);
  auto s = [](const timeval& t) { return static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_usec); };
  r.cpu_s = s(u.ru_utime) + s(u.ru_stime);
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 1;
  return r;
}

std::string scene_path(const std::string& file) {
  namespace fs = std::filesystem;
  std::vector<fs::path> dirs;
  if (const char* env = std::getenv("RANGESIM_SCENE_DIR"); env && *env) dirs.emplace_back(env);
  std::error_code ec;
  const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
  if (!ec) dirs.push_back(exe.parent_path().parent_path() / "share/rangesim/scenes");
  dirs.emplace_back(RANGESIM_SOURCE_SCENE_DIR);
  for (const auto& d : dirs)
    if (fs::is_regular_file(d / file)) return (d / file).string();
  throw UserError(
      fmt::format("bench: scene file {} not found in $RANGESIM_SCENE_DIR, <prefix>/share/rangesim/scenes or {}", file,
                  RANGESIM_SOURCE_SCENE_DIR));
}

}  // namespace rangesim::app::bench
