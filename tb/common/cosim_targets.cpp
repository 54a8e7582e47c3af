// The co-simulation targets of `rangesim cosim` (tb/common/cosim_target.h): each shipped
// sensor's list (tb/<sensor>/cosim_targets.cpp, through core/sensor_list.h), sensors first.
#include <algorithm>
#include <string>

#include "core/sensor_list.h"
#include "tb/common/cosim_target.h"

namespace rangesim::tb {

#define RANGESIM_DECLARE(s) std::vector<CosimTarget> s##_cosim_targets();
RANGESIM_FOR_EACH_SENSOR(RANGESIM_DECLARE)
#undef RANGESIM_DECLARE

const std::vector<CosimTarget>& cosim_targets() {
  static const std::vector<CosimTarget> targets = [] {
    std::vector<CosimTarget> t;
#define RANGESIM_APPEND(s) \
  for (auto& x : s##_cosim_targets()) t.push_back(x);
    RANGESIM_FOR_EACH_SENSOR(RANGESIM_APPEND)
#undef RANGESIM_APPEND
    // Sensors first (their ids have '-', block names '_'), each group in listing order.
    std::stable_partition(t.begin(), t.end(), [](const CosimTarget& x) { return std::string(x.name).find('-') != std::string::npos; });
    return t;
  }();
  return targets;
}

}  // namespace rangesim::tb
