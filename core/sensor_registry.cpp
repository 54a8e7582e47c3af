#include "core/sensor_registry.h"

#include <fmt/format.h>

#include <stdexcept>

#include "core/sensor_list.h"
#include "core/user_error.h"

namespace rangesim {

// Each sensor's core part, defined in core/<sensor>/schema.cpp.
#define RANGESIM_DECLARE(s) const SensorInfo& s##_sensor_info();
RANGESIM_FOR_EACH_SENSOR(RANGESIM_DECLARE)
#undef RANGESIM_DECLARE

namespace {
std::vector<SensorInfo>& registry() {
  static std::vector<SensorInfo> list = {
#define RANGESIM_ENTRY(s) s##_sensor_info(),
      RANGESIM_FOR_EACH_SENSOR(RANGESIM_ENTRY)
#undef RANGESIM_ENTRY
  };
  return list;
}
}  // namespace

const std::vector<SensorInfo>& sensors() { return registry(); }

const SensorInfo* find_sensor(const std::string& id) {
  for (const auto& s : registry())
    if (s.id == id) return &s;
  return nullptr;
}

void register_sensor(const SensorInfo& info) {
  if (info.id.empty() || !info.schema || !info.validate)
    throw std::invalid_argument("register_sensor: id, schema and validate are required");
  if (find_sensor(info.id))
    throw std::invalid_argument("register_sensor: sensor " + info.id + " is registered already");
  registry().push_back(info);
}

std::string sensor_ids() {
  std::string ids;
  for (const auto& s : registry()) ids += (ids.empty() ? "" : ", ") + s.id;
  return ids;
}

const ParamSchema& schema_for(const std::string& sensor_id, const std::string& where) {
  if (const SensorInfo* s = find_sensor(sensor_id)) return s->schema();
  throw UserError(
      fmt::format("{}: sensor.id = \"{}\" is not a known sensor; allowed: {}", where, sensor_id, sensor_ids()));
}

SensorRadiometry radiometry_for(const ParamSet& p, const std::string& where) {
  const SensorInfo* s = find_sensor(p.sensor_id());
  if (!s || !s->radiometry)
    throw UserError(fmt::format("{}: sensor {} has no radiometry (it takes no physical scene or axis)", where,
                                p.sensor_id()));
  return s->radiometry(p);
}

}  // namespace rangesim
