#pragma once
// Files and JSON of an evaluation: CSV maps, summary.json keys (README "JSON keys").
#include <string>
#include <vector>

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

// The same files a row at a time (app/grid_writer.h streams them): the header line, then the
// lines of background row `ib` (points.csv: one per point; a matrix: one).
std::string points_csv_header(const golden::EvalResult& ev);
std::string points_csv_rows(const std::vector<golden::EvalPoint>& row);
// Matrix cells: "detect", "accuracy_mm" or a metric name.
std::string matrix_csv_header(const golden::EvalResult& ev);
std::string matrix_csv_row(const golden::EvalResult& ev, double background, const std::vector<golden::EvalPoint>& row,
                           const std::string& cell);

// summary.json: stable snake_case keys with units.
nlohmann::json summary_json(const golden::EvalResult& ev, const ParamSet& params);

// The summary as an aligned table for the terminal.
std::string summary_text(const golden::EvalResult& ev);

}  // namespace rangesim::app
