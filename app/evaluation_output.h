#pragma once
// Files and JSON of an evaluation: CSV maps, summary.json keys (README "JSON keys").
#include <string>

#include <nlohmann/json.hpp>

#include "core/params.h"
#include "golden/common/sensor_evaluation.h"

namespace rangesim::app {

// One line per operating point: signal, background, detect, SBR' both ways, accuracy, metrics.
std::string points_csv(const golden::EvalResult& ev);

// Matrix (rows background, columns signal) of a cell text per point.
std::string detect_matrix_csv(const golden::EvalResult& ev);
// Matrix of accuracy in mm, or of a named metric; empty where not detectable.
std::string accuracy_mm_matrix_csv(const golden::EvalResult& ev);
std::string metric_matrix_csv(const golden::EvalResult& ev, const std::string& metric);

// summary.json: stable snake_case keys with units.
nlohmann::json summary_json(const golden::EvalResult& ev, const ParamSet& params);

// The summary as an aligned table for the terminal.
std::string summary_text(const golden::EvalResult& ev);

}  // namespace rangesim::app
