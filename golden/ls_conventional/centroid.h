#pragma once
// Centre of the activated pixels of one sampling, and the combination over samplings.
//
// The thesis's centroid (eq. 2.6, 3.8, 3.9) divides by sum(x_i); the centroid is
// sum(V_i x_i) / sum(V_i) (the thesis divides by sum(x_i), a fault). When nothing is activated the sum of weights is
// zero and the result is an explicit "no detection", never a division by zero.
#include <vector>

namespace rangesim::golden {

struct CentreEstimate {
  bool detected = false;  // false: no pixel activated, centre_px is meaningless (0)
  double centre_px = 0;   // estimated spot centre, pixels
};

// sum(w_i x_i) / sum(w_i) over pixels at positions x_i with non-negative weights (codes).
CentreEstimate weighted_centroid(const std::vector<double>& positions_px, const std::vector<double>& weights);

// 1-bit readout: (left + right) / 2 of the leftmost and rightmost activated pixels (the two column
// addresses the chained search streams out).
CentreEstimate edge_centre(const std::vector<double>& positions_px, const std::vector<bool>& active);

// Multi-sampling combination: mean of the centres of the samplings that detected something.
CentreEstimate mean_of_detections(const std::vector<CentreEstimate>& per_sampling);

}  // namespace rangesim::golden
