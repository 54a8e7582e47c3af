#pragma once
// The signal and background axes of a grid evaluation. The command's grids are log-spaced from the
// preset's `evaluation.*_min/max/points` (the flags set those); a caller with its own axis values
// (the Python module's evaluate(signal=array)) puts them in a GridAxesScope around the
// evaluation, on the thread that calls it, and every sensor's model reads them through
// grid_axis(): the preset's ends and count must be the values' own (the caller sets them so).
#include <optional>
#include <vector>

namespace rangesim::golden {

enum class GridAxis { Signal, Background };

// The explicit values for `axis` while a scope lives on this thread and they have the preset
// axis's ends and count (values equal to the preset axis to 1e-12 give the preset axis itself);
// otherwise `preset_axis` (the model's own log-spaced axis).
std::vector<double> grid_axis(GridAxis axis, std::vector<double> preset_axis);

// Explicit axis values for the evaluations on this thread while it lives; an empty vector leaves
// that axis log-spaced. Scopes do not nest.
class GridAxesScope {
 public:
  GridAxesScope(std::vector<double> signal, std::vector<double> background);
  ~GridAxesScope();
  GridAxesScope(const GridAxesScope&) = delete;
  GridAxesScope& operator=(const GridAxesScope&) = delete;
};

}  // namespace rangesim::golden
