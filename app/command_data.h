#pragma once
// What `list`, `show`, `frame-rate` and `table` print with --json, as data: the commands print
// it, the Python module (python/) returns it, so both give the same values under the same keys.
#include <nlohmann/json.hpp>

#include "core/params.h"
#include "golden/common/evaluate_sensor.h"
#include "golden/common/frame_timing.h"

namespace rangesim::app {

// A command that runs only for the sensors its level's registry holds (simulate, evaluate --trials,
// cosim). `list` asks each one registered; the registries live in libraries this one does not
// link, so the program that links them registers the question (app/main.cpp, python/module.cpp).
struct SensorCommand {
  std::string name;                        // as on the command line, e.g. "simulate"
  bool (*runs)(const std::string& sensor);  // whether it runs for this sensor id
};
void add_sensor_command(const SensorCommand& c);

// `list --json`: every registered sensor, which commands run for it and its preset file.
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
