#pragma once
// The command line of `rangesim`, parsed without running anything: main() runs the parsed
// command, and the CLI fuzz target (fuzz/cli_fuzz.cpp) calls parse_command_line() on arbitrary
// argv. Only CLI11 and the option structs of commands.h are needed here.
#include <iosfwd>
#include <optional>
#include <string>

#include "app/cmd_simulate.h"
#include "app/commands.h"
#include "app/compare/compare.h"

namespace rangesim::app {

enum class CommandKind { None, List, Show, Evaluate, FrameRate, Table, Simulate, Bench, Cosim, Sweep, Merge, Compare };

// One parsed command line: which subcommand, and its options.
struct ParsedCommand {
  CommandKind kind = CommandKind::None;
  ListOptions list;
  ShowOptions show;
  EvaluateOptions evaluate;
  FrameRateOptions frame_rate;
  TableOptions table;
  SimulateOptions simulate;
  BenchOptions bench;
  CosimCommandOptions cosim;
  SweepOptions sweep;
  MergeOptions merge;
  CompareOptions compare;
  // Budgets of the long commands (app/run_control.h); evaluate's --max-seconds is its own option.
  std::optional<double> max_seconds;
  std::string max_memory;  // "" = none; checked text (app/cli_checks.h)
};

struct CommandLine {
  // true: the parse already produced the process's answer (help, version or a usage error was
  // printed to `out` / `err`); exit with `exit_code` without running a command.
  bool finished = false;
  int exit_code = 0;
  ParsedCommand command;  // valid when !finished
};

// Parses argv (argv[0] is the program name). Prints --help / --version to `out`, usage errors to
// `err` (exit code 2, kExitBadInput). Never throws for any argv; never touches files.
CommandLine parse_command_line(int argc, const char* const* argv, std::ostream& out, std::ostream& err);

}  // namespace rangesim::app
