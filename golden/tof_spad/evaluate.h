#pragma once
// tof-spad evaluation over signal x background count rates (thesis 4.2.2, completed) and its
// published figures, from a config (tests vary it) or a preset (golden/common/evaluate_sensor.h).
#include <vector>

#include "core/tof_spad/config.h"
#include "golden/common/evaluate_sensor.h"

namespace rangesim::golden::spad {

// The grid's points are kept in EvalResult::points, or handed to `sink` row by row.
EvalResult evaluate_grid(const TofSpadConfig& cfg, ProgressFn progress = nullptr, EvalSink* sink = nullptr);
std::vector<PublishedFigure> published_figures(const TofSpadConfig& cfg);

// Metric names of EvalPoint::metrics, in order.
inline const std::vector<std::string>& metric_names() {
  static const std::vector<std::string> names = {
      "bias_m", "std_m", "signal_counts", "background_counts", "detections_per_cycle", "armed_at_echo"};
  return names;
}

}  // namespace rangesim::golden::spad
