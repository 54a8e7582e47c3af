// `rangesim cosim` in a build without Verilator (RANGESIM_WITH_RTL=OFF): no RTL to co-simulate.
#include "app/cli_common.h"
#include "app/commands.h"

namespace rangesim::app {

bool cosim_runs(const std::string&) { return false; }

int run_cosim(const CosimCommandOptions&) {
  throw NotModelled{"rangesim cosim: this build has no RTL (configured with RANGESIM_WITH_RTL=OFF)"};
}

}  // namespace rangesim::app
