// rangesim: command-line entry point. The command line is parsed by parse_command_line()
// (cli_parse.cpp), subcommands live in cmd_*.cpp; this file only runs the parsed command and maps
// errors to exit codes (0 ok, 1 internal, 2 bad input, 3 not modelled yet; run_evaluate_mc also
// returns 4 and 130 for a sweep stopped by its time budget or Ctrl-C).
#include <fmt/format.h>
#include <iostream>

#include "app/cli_common.h"
#include "app/cli_parse.h"
#include "app/cmd_simulate.h"
#include "app/commands.h"
#include "core/user_error.h"

using namespace rangesim::app;

namespace {

int run(const ParsedCommand& c) {
  switch (c.kind) {
    case CommandKind::List: return run_list(c.list);
    case CommandKind::Show: return run_show(c.show);
    case CommandKind::Evaluate:
      return c.evaluate.trials || c.evaluate.target_error || c.evaluate.resume ? run_evaluate_mc(c.evaluate)
                                                                               : run_evaluate(c.evaluate);
    case CommandKind::FrameRate: return run_frame_rate(c.frame_rate);
    case CommandKind::Table: return run_table(c.table);
    case CommandKind::Simulate: return run_simulate(c.simulate);
    case CommandKind::Bench: return run_bench(c.bench);
    case CommandKind::Cosim: return run_cosim(c.cosim);
    case CommandKind::Sweep: return run_sweep(c.sweep);
    case CommandKind::Merge: return run_merge(c.merge);
    case CommandKind::None: break;
  }
  return kExitInternal;
}

}  // namespace

int main(int argc, char** argv) {
  const CommandLine cl = parse_command_line(argc, argv, std::cout, std::cerr);
  if (cl.finished) return cl.exit_code;
  try {
    return run(cl.command);
  } catch (const rangesim::UserError& e) {
    fmt::print(stderr, "rangesim: error: {}\n", e.what());
    return kExitBadInput;
  } catch (const NotModelled& e) {
    fmt::print(stderr, "{}\n", e.message);
    return kExitNotModelled;
  } catch (const std::exception& e) {
    fmt::print(stderr, "rangesim: internal error: {}\n", e.what());
    return kExitInternal;
  }
}
