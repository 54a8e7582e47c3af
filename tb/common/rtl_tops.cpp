// The RTL tops of every shipped sensor (core/sensor_list.h): see rtl_tops.h.
#include "tb/common/rtl_tops.h"

#include "core/sensor_list.h"
#include "core/sensor_registry.h"
#include "core/user_error.h"

namespace rangesim {
#define RANGESIM_DECLARE(s) const SensorInfo& s##_sensor_info();
RANGESIM_FOR_EACH_SENSOR(RANGESIM_DECLARE)
#undef RANGESIM_DECLARE
}  // namespace rangesim

namespace rangesim::tb {

#define RANGESIM_DECLARE(s) std::vector<RtlTop> s##_rtl_tops();
RANGESIM_FOR_EACH_SENSOR(RANGESIM_DECLARE)
#undef RANGESIM_DECLARE

namespace {

struct SensorTops {
  std::string sensor_id;
  std::vector<RtlTop> tops;
};

const std::vector<SensorTops>& all_tops() {
  static const std::vector<SensorTops> all = [] {
    std::vector<SensorTops> v;
#define RANGESIM_APPEND(s) v.push_back({s##_sensor_info().id, s##_rtl_tops()});
    RANGESIM_FOR_EACH_SENSOR(RANGESIM_APPEND)
#undef RANGESIM_APPEND
    return v;
  }();
  return all;
}

}  // namespace

VerilogParameters rtl_top_parameters(const ParamSet& preset, const std::string& top) {
  std::string known;
  for (const auto& s : all_tops()) {
    if (s.sensor_id != preset.sensor_id()) continue;
    for (const auto& t : s.tops) {
      if (top == t.top) return t.parameters(preset);
      known += (known.empty() ? "" : ", ") + std::string(t.top);
    }
  }
  throw UserError(preset.origin() + ": a " + preset.sensor_id() + " preset has no RTL top '" + top +
                  "'; its tops: " + (known.empty() ? "none" : known));
}

}  // namespace rangesim::tb
