// `rangesim cosim` in a build without Verilator (RANGESIM_WITH_RTL=OFF): no RTL to co-simulate.
#include "app/cli_common.h"
#include "app/commands.h"

namespace rangesim::app {

int run_cosim(const CosimCommandOptions&) {
  throw NotModelled{"rangesim cosim: this build has no RTL (configured with RANGESIM_WITH_RTL=OFF)"};
}

}  // namespace rangesim::app
