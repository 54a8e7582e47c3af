// load_modelled_preset (app/cli_common.h): apart from the flag helpers so the command-line fuzz
// target (fuzz/cli_fuzz.cpp) links those without the models.
#include <fmt/format.h>

#include "app/cli_common.h"
#include "core/preset.h"
#include "golden/common/evaluate_sensor.h"

namespace rangesim::app {

ParamSet load_modelled_preset(const std::string& id_or_path, const std::string& command,
                              const std::vector<std::string>& settings) {
  ParamSet params = load_preset(id_or_path);
  apply_settings(params, settings);
  require_modelled(params, command);
  return params;
}

void require_modelled(const ParamSet& params, const std::string& command) {
  if (!golden::golden_model(params.sensor_id())) {
    std::string modelled;
    for (const auto& s : sensors())
      if (golden::golden_model(s.id)) modelled += (modelled.empty() ? "" : ", ") + s.id;
    throw NotModelled{
        fmt::format("rangesim {}: sensor '{}' is not modelled yet (its preset loads and validates; "
                    "see `rangesim show {}`); modelled: {}",
                    command, params.sensor_id(), params.sensor_id(), modelled)};
  }
}

}  // namespace rangesim::app
