// Child processes of the run-time verilation: see rtl_process.h.
#include "tb/common/rtl_process.h"

#include <fcntl.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace rangesim::tb {

// Absolute path of `name` on PATH ("" if absent); a name with '/' is checked as it is.
std::string find_program(const std::string& name) {
  if (name.find('/') != std::string::npos) return access(name.c_str(), X_OK) == 0 ? name : "";
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path ? path : "");
  for (std::string d; std::getline(dirs, d, ':');) {
    const std::string p = (d.empty() ? "." : d) + "/" + name;
    if (access(p.c_str(), X_OK) == 0) return p;
  }
  return "";
}

void die_with_parent(pid_t parent) {
  prctl(PR_SET_PDEATHSIG, SIGTERM);
  if (getppid() != parent) _exit(143);  // it is gone already
}

// Runs argv in `cwd` with stdout and stderr to `log` ("" = this process's stderr); exit status.
int run_program(const std::vector<std::string>& args, const std::string& cwd, const std::string& log) {
  const pid_t parent = getpid();
  const pid_t pid = fork();
  if (pid < 0) throw std::runtime_error("cosim: fork failed");
  if (pid == 0) {
    die_with_parent(parent);
    if (!cwd.empty() && chdir(cwd.c_str()) != 0) _exit(127);
    const int fd = log.empty() ? dup(STDERR_FILENO) : open(log.c_str(), O_WRONLY | O_CREAT | O_APPEND, 0644);
    if (fd < 0) _exit(127);
    dup2(fd, STDOUT_FILENO);
    dup2(fd, STDERR_FILENO);
    close(fd);
    std::vector<char*> argv;
    for (const auto& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    execv(args[0].c_str(), argv.data());
    _exit(127);
  }
  int status = 0;
  while (waitpid(pid, &status, 0) < 0) {
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
}

std::string log_tail(const std::string& path, int lines) {
  std::vector<std::string> v;
  std::ifstream in(path);
  for (std::string l; std::getline(in, l);) v.push_back(l);
  std::string s;
  for (std::size_t i = v.size() > static_cast<std::size_t>(lines) ? v.size() - lines : 0; i < v.size(); ++i)
    s += "  " + v[i] + "\n";
  return s;
}

}  // namespace rangesim::tb
