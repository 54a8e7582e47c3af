#pragma once
// Output helpers shared by the `rangesim simulate` commands of all sensors.
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/output_dir.h"

namespace rangesim::app {

// Number for CSV ("" for NaN/inf) and for JSON (null for NaN/inf).
std::string csv_number(double v);
nlohmann::json json_number(double v);

// range_map.csv: a header "row,<column names>", then one line per row of `map` (values in m,
// empty where there is no range).
std::string range_map_csv(const std::vector<std::vector<double>>& map, const std::vector<std::string>& column_names);

// Stages range_map.png: a gnuplot image of `map` (rows of values in m; NaN = no range) with
// the given axis labels. Returns "" or a warning (gnuplot missing/failed; nothing left behind).
std::string render_range_map(OutputDir& out, const std::vector<std::vector<double>>& map, const std::string& title,
                             const std::string& x_label, const std::string& y_label = "row");

}  // namespace rangesim::app
