#pragma once
// What `list`, `show`, `frame-rate` and `table` print with --json, as data: the commands print
// it, the Python module (python/) returns it, so both give the same values under the same keys.
#include <nlohmann/json.hpp>

#include "core/params.h"
#include "golden/common/evaluate_sensor.h"
#include "golden/common/frame_timing.h"

namespace rangesim::app {

// `list --json`: every registered sensor, what is modelled and its preset file.
nlohmann::json list_json();

// `show --json`: the resolved parameters with unit, source, file, meaning and allowed range.
nlohmann::json show_json(const ParamSet& params);

// `frame-rate --samplings N`: sets multisampling.samplings, or throws UserError for a sensor without it.
void apply_frame_rate_samplings(ParamSet& params, int samplings);
// The clock schedule's keys (samplings, clock_Hz, frame_cycles, ..., phases).
nlohmann::json frame_timing_json(const golden::FrameTiming& t);
// `frame-rate --json`: frame_timing_json of the preset's schedule plus sensor and preset.
nlohmann::json frame_rate_json(const ParamSet& params);

// `table --json` (and table5_1.json): thesis Table 5.1 beside each preset's default evaluation
// and the chips' published figures. `progress` as in golden::evaluate_sensor (it may throw to stop).
nlohmann::json table_json(golden::ProgressFn progress = nullptr);

}  // namespace rangesim::app
