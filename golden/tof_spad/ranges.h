#pragma once
// Exact edges of the detectable interval along one axis (bisection between grid points) and the
// range nonlinearity over distance: the summary figures that evaluate.cpp and the published
// figures share.
#include <functional>
#include <vector>

#include "golden/common/sensor_evaluation.h"
#include "golden/tof_spad/point_model.h"

namespace rangesim::golden::spad {

// Detectable interval of `detectable(x)` over the ascending log-spaced `axis`: the first run of
// detectable grid points, edges refined by bisection in log x (to 1e-4 relative) where the edge
// lies between grid points; flags say when an edge is the grid's end.
EvalRange detectable_range(const std::vector<double>& axis, const std::vector<bool>& grid_detectable,
                           const std::function<bool(double)>& detectable, double at);

// Bias of the range against the distance on `distances`, and its largest deviation from the
// least-squares straight line (offset and gain calibrated away, as a range camera is).
struct Nonlinearity {
  std::vector<double> distance_m, bias_m, std_m;
  double max_deviation_m = 0;  // max |bias - best line|
  double max_abs_bias_m = 0;   // max |bias| without the line fit
};
Nonlinearity nonlinearity(const SpadModel& model, double signal_Hz, double background_Hz,
                          const std::vector<double>& distances_m);

std::vector<double> linear_spaced(double lo, double hi, int n);

}  // namespace rangesim::golden::spad
