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

// One quantity golden is compared on at a point (docs/evaluate-montecarlo.md, "Agreement"): the
// accuracy (of the trials without an outlier where the model splits them off, else of all), and
// where the model gives them, the detection and outlier probabilities.
struct McComparison {
  std::string quantity;               // "accuracy_clean_m", "accuracy_m", "p_detect" or "p_outlier"
  double golden = 0;                  // golden's value (m or probability)
  McInterval mc;                      // the MC's value and 95% CI (m or probability)
  double gap_half_widths = 0;         // |golden - MC| in half-widths of the CI on golden's side
  bool inside = false;                // golden inside the 95% CI
  bool within_2_half_widths = false;  // the stated test (tests/montecarlo/test_mc_golden.cpp)
};
// Every quantity compared at grid point i (run there).
std::vector<McComparison> mc_comparisons(const McGrid& g, std::size_t i);

// A quantity at a point where golden falls outside the MC's 95% CI.
struct McOutsidePoint {
  std::size_t index = 0;              // grid index (row-major)
  double signal = 0, background = 0;  // sensor units
  McComparison c;
  double p_detect = 0;  // MC detection probability
  double gap_rel = 0;   // (golden - MC) / MC
};
// Every compared quantity outside the CI, in grid order.
std::vector<McOutsidePoint> mc_golden_outside_ci(const McGrid& g);
// mc_golden_outside_ci.csv: those, one a line (a header only when there are none).
std::string mc_outside_csv(const McGrid& g);

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
