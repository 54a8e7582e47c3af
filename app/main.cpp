// rangesim: command-line entry point. The command line is parsed by parse_command_line()
// (cli_parse.cpp), subcommands live in cmd_*.cpp; this file only runs the parsed command and maps
// errors to exit codes (0 ok, 1 internal, 2 bad input, 3 not modelled yet, 4 a budget ran out; a
// run stopped by a signal exits with 128 + the signal, app/run_control.h).
#include <fmt/format.h>
#include <iostream>
#include <new>

#include "app/cli_checks.h"
#include "app/cli_common.h"
#include "app/cli_parse.h"
#include "app/cmd_simulate.h"
#include "app/command_data.h"
#include "app/commands.h"
#include "app/large_array_pages.h"
#include "app/run_control.h"
#include "core/user_error.h"
#include "systemc/common/montecarlo.h"

using namespace rangesim::app;

namespace {

// The commands whose registries this program links, for `list`.
void register_sensor_commands() {
  add_sensor_command({"simulate", &simulate_runs});
  add_sensor_command({"evaluate --trials", &rangesim::mc::has_mc_model});
  add_sensor_command({"cosim", &cosim_runs});
}

int run(const ParsedCommand& c) {
  switch (c.kind) {
    case CommandKind::List: return run_list(c.list);
    case CommandKind::Show: return run_show(c.show);
    case CommandKind::Evaluate:
      return c.evaluate.trials || c.evaluate.target_error || c.evaluate.resume ? run_evaluate_mc(c.evaluate)
                                                                               : run_evaluate(c.evaluate);
    case CommandKind::FrameRate: return run_frame_rate(c.frame_rate);
    case CommandKind::Table: return run_table(c.table);
    case CommandKind::Simulate:
      heap_on_huge_pages();  // a scene run's results are tens of MB of fresh heap
      return run_simulate(c.simulate);
    case CommandKind::Bench: return run_bench(c.bench);
    case CommandKind::Cosim: return run_cosim(c.cosim);
    case CommandKind::Sweep: return run_sweep(c.sweep);
    case CommandKind::Merge: return run_merge(c.merge);
    case CommandKind::Compare: return run_compare(c.compare);
    case CommandKind::None: break;
  }
  return kExitInternal;
}

// The budgets of the run from its flags (checked by the parser already).
RunBudget budget_of(const ParsedCommand& c) {
  RunBudget b;
  const std::optional<double> seconds = c.kind == CommandKind::Evaluate ? c.evaluate.max_seconds : c.max_seconds;
  if (seconds) b.max_seconds = *seconds, b.max_seconds_text = fmt::format("{}", *seconds);
  if (!c.max_memory.empty()) {
    std::string text = c.max_memory;
    check_memory_text(text, b.max_memory_bytes);
    b.max_memory_text = c.max_memory;
  }
  return b;
}

}  // namespace

int main(int argc, char** argv) {
  install_stop_handlers();
  set_command_line(argc, argv);
  const CommandLine cl = parse_command_line(argc, argv, std::cout, std::cerr);
  if (cl.finished) return cl.exit_code;
  start_budget(budget_of(cl.command));
  register_sensor_commands();
  try {
    return run(cl.command);
  } catch (const std::bad_alloc&) {
    // The estimates refuse what cannot fit up front; this is the memory that ran out regardless.
    fmt::print(stderr,
               "rangesim: out of memory ({} resident); nothing written; reduce the work (grid points, trials, "
               "variants, frames) or give --max-memory to be refused up front\n",
               bytes_text(static_cast<double>(resident_bytes())));
    return kExitBudget;
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
