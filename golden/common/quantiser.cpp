#include "golden/common/quantiser.h"

#include <algorithm>
#include <cmath>

#include "golden/common/pixel.h"

namespace rangesim::golden {

double comparator_threshold_V(const LsConventionalConfig& cfg, double background_V) {
  if (cfg.comparator.threshold_mode == ThresholdMode::Fixed) return cfg.comparator.fixed_threshold_V;
  return output_voltage_V(cfg.pixel, background_V + dark_voltage_V(cfg.pixel)) +
         cfg.comparator.threshold_above_background_V;
}

Quantiser make_quantiser(const LsConventionalConfig& cfg, double background_V) {
  Quantiser q;
  q.bits = cfg.comparator.adc_bits;
  q.max_code = static_cast<int>((1LL << q.bits) - 1);
  q.threshold_V = comparator_threshold_V(cfg, background_V);
  q.lsb_V = cfg.comparator.threshold_above_background_V;
  q.ref_V = q.threshold_V - q.lsb_V;
  return q;
}

double code_threshold_V(const Quantiser& q, int m) { return q.threshold_V + (m - 1) * q.lsb_V; }

int quantise(const Quantiser& q, double output_V) {
  // Comparisons against the code thresholds (not a floor of a quotient) so that code >= m holds
  // exactly when output_V >= code_threshold_V(q, m), the form the analytic breakpoints use.
  if (output_V < q.threshold_V) return 0;
  const double steps = std::floor((output_V - q.threshold_V) / q.lsb_V);
  int c = 1 + static_cast<int>(std::min<double>(steps, q.max_code));
  c = std::min(c, q.max_code);
  // Guard the floor against rounding at a code edge.
  while (c < q.max_code && output_V >= code_threshold_V(q, c + 1)) ++c;
  while (c > 1 && output_V < code_threshold_V(q, c)) --c;
  return c;
}

}  // namespace rangesim::golden
