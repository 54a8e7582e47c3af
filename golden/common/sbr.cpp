#include "golden/common/sbr.h"

#include <cmath>

namespace rangesim::golden {

double sbr_total_dB(double signal_V, double background_V) {
  return 20.0 * std::log10((signal_V + background_V) / background_V);
}

double sbr_ratio_dB(double signal_V, double background_V) { return 20.0 * std::log10(signal_V / background_V); }

}  // namespace rangesim::golden
