#pragma once
// Runs a shell command and captures its exit code, stdout and stderr.
#include <string>

struct CommandResult {
  int exit_code = -1;
  std::string out;
  std::string err;
};

CommandResult run_command(const std::string& command);

// Makes a fresh temporary directory for one test.
std::string make_temp_dir();

// The whole content of a file ("" when it cannot be read).
std::string read_text_file(const std::string& path);
