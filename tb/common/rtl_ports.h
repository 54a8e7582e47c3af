#pragma once
// Bring-your-own RTL (`rangesim cosim <target> --rtl FILE.sv`): a user's module replaces the
// rangesim block of the same name inside the co-simulated readout, so it must have that block's
// ports (docs/rtl-contract.md). The contract is rangesim's own module as Verilator elaborates it
// at the instance's parameters: port names, directions and widths, read from Verilator's XML
// (--xml-only), so the check and the RTL cannot drift apart.
#include <string>
#include <vector>

#include "core/params.h"
#include "tb/common/verilog_parameters.h"

namespace rangesim::tb {

struct RtlPort {
  std::string name;
  std::string direction;  // "input", "output", "inout"
  int width = 1;          // bits
  bool operator==(const RtlPort& o) const { return name == o.name && direction == o.direction && width == o.width; }
};

// The modules a Verilog file defines (comments ignored), in order.
std::vector<std::string> modules_defined_in(const std::string& file);

// Where the elaboration of `module` runs: Verilator, the files it reads (first definition wins,
// -y folders for the rest) and a scratch folder for the XML.
struct RtlElaboration {
  std::string verilator;
  std::vector<std::string> files;
  std::vector<std::string> search_dirs;
  std::string rtl_dir;  // working folder (rtl/: rtl/verilator.f is relative to it)
  std::string scratch;
};

// Ports of `module` elaborated with `parameters` (Verilog defaults for the rest), and the names
// of every module in its hierarchy. UserError with Verilator's own message (file:line) when the
// files do not parse or elaborate.
struct ElaboratedModule {
  std::vector<RtlPort> ports;
  std::vector<std::string> hierarchy;  // module names under (and including) `module`
};
ElaboratedModule elaborate_module(const RtlElaboration& e, const std::string& module,
                                  const VerilogParameters& parameters);

// UserError naming `file`, the module and each port that is missing, extra, of another direction
// or of another width than the contract `want` (at `parameters`).
void check_port_contract(const std::string& file, const std::string& module, const std::vector<RtlPort>& want,
                         const std::vector<RtlPort>& have, const VerilogParameters& parameters);

}  // namespace rangesim::tb
