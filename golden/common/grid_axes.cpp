#include "golden/common/grid_axes.h"

#include <cmath>
#include <utility>

namespace rangesim::golden {

namespace {
thread_local std::vector<double> t_axes[2];
}  // namespace

std::vector<double> grid_axis(GridAxis axis, std::vector<double> preset_axis) {
  const std::vector<double>& v = t_axes[static_cast<int>(axis)];
  if (v.empty() || v.size() != preset_axis.size() || v.front() != preset_axis.front() || v.back() != preset_axis.back())
    return preset_axis;
  // Values that are the preset's axis to rounding (numpy.geomspace of the same ends) give the
  // command's grid bit for bit.
  for (std::size_t i = 0; i < v.size(); ++i)
    if (std::fabs(v[i] - preset_axis[i]) > 1e-12 * std::fabs(preset_axis[i])) return v;
  return preset_axis;
}

GridAxesScope::GridAxesScope(std::vector<double> signal, std::vector<double> background) {
  t_axes[0] = std::move(signal);
  t_axes[1] = std::move(background);
}

GridAxesScope::~GridAxesScope() { t_axes[0].clear(), t_axes[1].clear(); }

}  // namespace rangesim::golden
