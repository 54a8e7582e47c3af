#include "systemc/common/montecarlo.h"

#include <stdexcept>

#include "core/sensor_list.h"
#include "core/sensor_registry.h"
#include "systemc/common/random_stream.h"

namespace rangesim {
// The core part of each shipped sensor (core/<sensor>/schema.cpp): its id.
#define RANGESIM_DECLARE(s) const SensorInfo& s##_sensor_info();
RANGESIM_FOR_EACH_SENSOR(RANGESIM_DECLARE)
#undef RANGESIM_DECLARE
}  // namespace rangesim

namespace rangesim::mc {

// Each shipped sensor's model, defined in systemc/<sensor>/montecarlo.cpp.
#define RANGESIM_DECLARE(s) std::unique_ptr<McModel> make_##s##_mc(const ParamSet& params);
RANGESIM_FOR_EACH_SENSOR(RANGESIM_DECLARE)
#undef RANGESIM_DECLARE

namespace {
std::vector<std::pair<std::string, McFactory>>& mc_registry() {
  static std::vector<std::pair<std::string, McFactory>> list = {
#define RANGESIM_ENTRY(s) {s##_sensor_info().id, &make_##s##_mc},
      RANGESIM_FOR_EACH_SENSOR(RANGESIM_ENTRY)
#undef RANGESIM_ENTRY
  };
  return list;
}
}  // namespace

using systemc::splitmix64;

std::uint64_t point_key(std::uint64_t seed, std::uint64_t point_index) {
  return splitmix64(splitmix64(seed ^ 0x6d6f6e7465636172ULL) ^ point_index);  // "montecar"
}

std::uint64_t trial_key(std::uint64_t key, std::uint64_t trial) { return splitmix64(key ^ splitmix64(trial)); }

double trial_uniform(std::uint64_t key, std::uint64_t trial) {
  pcg32 rng = systemc::pixel_stream(trial_key(key ^ 0x706f736974696f6eULL, trial));  // "position"
  return systemc::uniform_open01(rng);
}

std::unique_ptr<McModel> make_mc_model(const ParamSet& params) {
  for (const auto& [id, make] : mc_registry())
    if (id == params.sensor_id()) return make(params);
  throw std::logic_error("no Monte Carlo model for sensor " + params.sensor_id());
}

void register_mc_model(const std::string& sensor_id, McFactory make) { mc_registry().emplace_back(sensor_id, make); }

bool has_mc_model(const std::string& sensor_id) {
  for (const auto& [id, make] : mc_registry())
    if (id == sensor_id) return true;
  return false;
}

}  // namespace rangesim::mc
