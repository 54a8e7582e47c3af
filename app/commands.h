#pragma once
// The rangesim subcommands. Each returns the process exit code (see cli_common.h) and throws
// UserError for bad input, NotModelled for a sensor without a model for the command.
#include <optional>
#include <string>

namespace rangesim::app {

struct ListOptions {
  bool json = false;
};
int run_list(const ListOptions& opt);

struct ShowOptions {
  std::string preset;  // id or path
  bool json = false;
};
int run_show(const ShowOptions& opt);

struct EvaluateOptions {
  std::string sensor;                 // preset id or path
  std::optional<std::string> signal;  // "LO:HI:N" volts
  std::optional<std::string> background;
  std::optional<int> samplings;
  std::optional<int> adc_bits;
  std::optional<int> frames;          // frames averaged
  std::string out;                    // output directory ("" -> rangesim-out/<sensor>)
  bool json = false;
  bool no_plots = false;
};
int run_evaluate(const EvaluateOptions& opt);

struct FrameRateOptions {
  std::string sensor;
  std::optional<int> samplings;
  bool json = false;
};
int run_frame_rate(const FrameRateOptions& opt);

struct TableOptions {
  bool json = false;
  bool published = false;  // also list the chips' published figures on the terminal
  std::string out;         // "" -> nothing written
};
int run_table(const TableOptions& opt);

// `rangesim cosim` (app/cmd_cosim.cpp): RTL co-simulation targets of tb/cosim_targets.cpp.
inline constexpr int kExitCosimMismatch = 4;  // the run completed and found mismatches
struct CosimCommandOptions {
  std::string target;                   // sensor id, block name or "all" ("" with --list)
  std::optional<unsigned long long> cycles;  // clock cycles (default 100000)
  unsigned long long seed = 1;
  std::string trace;                    // RTL VCD file ("" = none)
  std::string junit;                    // JUnit XML file ("" = none)
  std::string inject_fault;             // a fault name of the target ("" = none)
  bool json = false;
  bool list = false;
};
int run_cosim(const CosimCommandOptions& opt);

}  // namespace rangesim::app
