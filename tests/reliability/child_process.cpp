#include "child_process.h"
#include "run_command.h"

#include <chrono>
#include <csignal>
#include <fcntl.h>
#include <stdexcept>
#include <sys/resource.h>
#include <sys/wait.h>
#include <thread>
#include <unistd.h>

namespace {

pid_t spawn(const std::vector<std::string>& argv, const std::string& cwd, const std::string& out,
            const std::string& err, unsigned long long address_space) {
  std::vector<char*> args;
  for (const auto& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  const pid_t pid = ::fork();
  if (pid < 0) throw std::runtime_error("fork failed");
  if (pid == 0) {
    // The child: only async-signal-safe calls until exec.
    if (::chdir(cwd.c_str()) != 0) ::_exit(127);
    const int o = ::open(out.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int e = ::open(err.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (o < 0 || e < 0) ::_exit(127);
    ::dup2(o, 1), ::dup2(e, 2);
    // A test run from a background job inherits ignored signals; the child must see them.
    struct sigaction dfl {};
    dfl.sa_handler = SIG_DFL;
    for (int sig : {SIGINT, SIGTERM, SIGHUP}) ::sigaction(sig, &dfl, nullptr);
    if (address_space > 0) {
      struct rlimit r {
        address_space, address_space
      };
      ::setrlimit(RLIMIT_AS, &r);
    }
    ::execv(args[0], args.data());
    ::_exit(127);
  }
  return pid;
}

ChildResult collect(pid_t pid, const std::string& out, const std::string& err, double wall_s) {
  ChildResult r;
  const auto t0 = std::chrono::steady_clock::now();
  int status = 0;
  struct rusage usage {};
  for (;;) {
    const pid_t w = ::wait4(pid, &status, WNOHANG, &usage);
    if (w == pid) break;
    r.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (r.wall_s > wall_s && !r.timed_out) {
      r.timed_out = true;
      ::kill(pid, SIGKILL);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  r.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.max_rss_kib = usage.ru_maxrss;
  if (WIFEXITED(status)) r.exit_code = WEXITSTATUS(status);
  if (WIFSIGNALED(status)) r.signal = WTERMSIG(status);
  r.out = read_text_file(out);
  r.err = read_text_file(err);
  ::unlink(out.c_str());
  ::unlink(err.c_str());
  return r;
}

}  // namespace

std::vector<std::string> split_args(const std::string& args) {
  std::vector<std::string> words;
  std::string w;
  bool quoted = false, any = false;
  for (char c : args) {
    if (c == '\'') {
      quoted = !quoted, any = true;
    } else if (c == ' ' && !quoted) {
      if (any) words.push_back(w);
      w.clear(), any = false;
    } else {
      w += c, any = true;
    }
  }
  if (any) words.push_back(w);
  return words;
}

ChildResult run_child(const std::vector<std::string>& argv, const std::string& cwd, const ChildLimits& limits) {
  const std::string out = cwd + "/../child.out." + std::to_string(::getpid());
  const std::string err = cwd + "/../child.err." + std::to_string(::getpid());
  return collect(spawn(argv, cwd, out, err, limits.address_space), out, err, limits.wall_s);
}

Background start_child(const std::vector<std::string>& argv, const std::string& cwd) {
  Background b;
  b.out_path = cwd + "/../bg.out." + std::to_string(::getpid());
  b.err_path = cwd + "/../bg.err." + std::to_string(::getpid());
  b.pid = spawn(argv, cwd, b.out_path, b.err_path, 0);
  return b;
}

ChildResult wait_child(const Background& b, double wall_s) { return collect(b.pid, b.out_path, b.err_path, wall_s); }
