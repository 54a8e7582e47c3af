#include "run_command.h"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <sys/wait.h>

std::string read_text_file(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string make_temp_dir() {
  char tmpl[] = "/tmp/rangesim-cli-XXXXXX";
  if (!mkdtemp(tmpl)) throw std::runtime_error("mkdtemp failed");
  return tmpl;
}

CommandResult run_command(const std::string& command) {
  const std::string dir = make_temp_dir();
  const std::string full = command + " >" + dir + "/out 2>" + dir + "/err";
  const int status = std::system(full.c_str());
  CommandResult r;
  r.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  r.out = read_text_file(dir + "/out");
  r.err = read_text_file(dir + "/err");
  std::system(("rm -rf " + dir).c_str());
  return r;
}
