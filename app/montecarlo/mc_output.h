#pragma once
// Files and JSON of a Monte Carlo evaluation (docs/evaluate-montecarlo.md): every accuracy value
// with its 95% confidence interval beside the golden closed form.
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "app/montecarlo/mc_stats.h"
#include "app/output_dir.h"
#include "golden/common/sensor_evaluation.h"

namespace rangesim::app::mc {

struct McGrid {
  const golden::EvalResult* ev = nullptr;          // the golden evaluation of the same grid
  std::vector<std::optional<McPointStats>> stats;  // per grid point (row-major), empty where not run
  const char* unit = "m";                          // model unit of the statistics
  double metres_per_unit = 1;
  long long trials = 0, max_trials = 0;
  double target_error_m = 0;
  unsigned long long seed = 1;
};

// One line per point run: golden accuracy, trials, p_detect, bias, std and accuracy (m) with CIs.
std::string mc_points_csv(const McGrid& g);
// Matrix (rows background, columns signal) of the MC accuracy in mm, or of its CI half-width.
std::string mc_matrix_csv(const McGrid& g, bool half_width);
// summary.json "monte_carlo" block.
nlohmann::json mc_summary_json(const McGrid& g);
// A few lines for the terminal.
std::string mc_summary_text(const McGrid& g);
// Stages mc_accuracy.{png,svg}: accuracy against signal with 95% error bars, a curve per background
// (up to 6), the golden closed form as lines. Returns "" or a warning (plots skipped).
std::string render_mc_plot(OutputDir& out, const McGrid& g);

}  // namespace rangesim::app::mc
