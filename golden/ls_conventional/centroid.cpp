#include "golden/ls_conventional/centroid.h"

#include <cassert>
#include <cstddef>

namespace rangesim::golden {

CentreEstimate weighted_centroid(const std::vector<double>& positions_px, const std::vector<double>& weights) {
  assert(positions_px.size() == weights.size());
  double sw = 0, swx = 0;
  for (std::size_t i = 0; i < weights.size(); ++i) {
    sw += weights[i];
    swx += weights[i] * positions_px[i];
  }
  if (!(sw > 0)) return {};
  return {true, swx / sw};
}

CentreEstimate edge_centre(const std::vector<double>& positions_px, const std::vector<bool>& active) {
  assert(positions_px.size() == active.size());
  int left = -1, right = -1;
  for (std::size_t i = 0; i < active.size(); ++i)
    if (active[i]) {
      if (left < 0) left = static_cast<int>(i);
      right = static_cast<int>(i);
    }
  if (left < 0) return {};
  return {true, 0.5 * (positions_px[left] + positions_px[right])};
}

CentreEstimate mean_of_detections(const std::vector<CentreEstimate>& per_sampling) {
  double sum = 0;
  int n = 0;
  for (const auto& c : per_sampling)
    if (c.detected) {
      sum += c.centre_px;
      ++n;
    }
  if (n == 0) return {};
  return {true, sum / n};
}

}  // namespace rangesim::golden
