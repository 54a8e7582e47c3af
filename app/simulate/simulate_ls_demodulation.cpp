// Placeholder until the clock-level model of ls-demodulation lands.
#include <fmt/format.h>

#include "app/cli_common.h"
#include "app/cmd_simulate.h"
#include "core/params.h"

namespace rangesim::app {

int run_simulate_ls_demodulation(const SimulateOptions&, const ParamSet& params) {
  throw NotModelled{fmt::format("rangesim simulate: sensor '{}' has no clock-level model yet; modelled: ls-conventional",
                                params.sensor_id())};
}

}  // namespace rangesim::app
