#pragma once
// range_map.png of `rangesim simulate`, the same plot for every sensor.
#include <string>
#include <vector>

#include "app/output_dir.h"

namespace rangesim::app {

// Stages range_map.png: a gnuplot image of `map` (rows of values in m; NaN = no range) with
// the given axis labels. Returns "" or a warning (gnuplot missing/failed; nothing left behind).
std::string render_range_map(OutputDir& out, const std::vector<std::vector<double>>& map, const std::string& title,
                             const std::string& x_label, const std::string& y_label = "row");

}  // namespace rangesim::app
