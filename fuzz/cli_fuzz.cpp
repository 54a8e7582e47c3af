// libFuzzer target: arbitrary argv through rangesim's command-line parser
// (app/cli_parse.h, parse_command_line) and the grid-flag parser; no command is ever run, no
// file is touched. The input is split into arguments at '\n' and '\0' (at most 64). Any
// exception, crash or sanitizer report is a finding. A parse either finishes with exit code 0
// (--help, --version) or 2 (usage error), or yields exactly one subcommand.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "app/cli_common.h"
#include "app/cli_parse.h"
#include "core/user_error.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  std::vector<std::string> args{"rangesim"};
  std::string cur;
  for (size_t i = 0; i < size && args.size() < 64; ++i) {
    const char c = static_cast<char>(data[i]);
    if (c == '\n' || c == '\0') {
      args.push_back(cur);
      cur.clear();
    } else {
      cur += c;
    }
  }
  if (!cur.empty() && args.size() < 64) args.push_back(cur);
  std::vector<const char*> argv;
  for (const auto& a : args) argv.push_back(a.c_str());

  std::ostringstream out, err;
  const rangesim::app::CommandLine cl =
      rangesim::app::parse_command_line(static_cast<int>(argv.size()), argv.data(), out, err);
  using rangesim::app::CommandKind;
  if (cl.finished) {
    if (cl.exit_code != 0 && cl.exit_code != rangesim::app::kExitBadInput) std::abort();
    if (cl.exit_code == rangesim::app::kExitBadInput && err.str().empty()) std::abort();
    return 0;
  }
  if (cl.command.kind == CommandKind::None) std::abort();
  // The option values a command would validate first (pure parsing, no files): grid axes.
  if (cl.command.kind == CommandKind::Evaluate) {
    for (const auto* g : {&cl.command.evaluate.signal, &cl.command.evaluate.background}) {
      if (!*g) continue;
      try {
        const rangesim::app::GridAxis a = rangesim::app::parse_grid_axis(**g, "--signal");
        if (!(a.lo > 0) || !(a.lo <= a.hi) || a.n < 1 || a.n > 10000) std::abort();
      } catch (const rangesim::UserError&) {
      }
    }
  }
  return 0;
}
