// The co-simulation targets of `rangesim cosim` (tb/common/cosim_target.h): each shipped
// sensor's list (tb/<sensor>/cosim_targets.cpp, through core/sensor_list.h), sensors first; and
// the sensors whose readout is co-simulated at a preset's own parameters (tb/common/rtl_build.h).
#include <algorithm>
#include <string>

#include "core/sensor_list.h"
#include "tb/common/cosim_target.h"
#include "tb/common/rtl_build.h"

namespace rangesim::tb {

#define RANGESIM_DECLARE(s)                     \
  std::vector<CosimTarget> s##_cosim_targets(); \
  std::vector<PresetCosim> s##_preset_cosims();
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
    std::stable_partition(t.begin(), t.end(),
                          [](const CosimTarget& x) { return std::string(x.name).find('-') != std::string::npos; });
    return t;
  }();
  return targets;
}

const std::vector<PresetCosim>& preset_cosims() {
  static const std::vector<PresetCosim> all = [] {
    std::vector<PresetCosim> v;
#define RANGESIM_APPEND(s) \
  for (auto& x : s##_preset_cosims()) v.push_back(x);
    RANGESIM_FOR_EACH_SENSOR(RANGESIM_APPEND)
#undef RANGESIM_APPEND
    return v;
  }();
  return all;
}

}  // namespace rangesim::tb
