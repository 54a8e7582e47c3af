#pragma once
// The core part of the sensor interface and the registry of sensors.
//
// A sensor's core part names it and owns its parameters: the preset schema and the function that
// builds its configuration from a validated preset (every derived integer computed there, every
// cross-key check made there). The analytic, clock-level and co-simulation parts live in the
// sensor's folders of golden/, systemc/ and tb/, each with a registry of its own keyed by the same
// id (golden/common/evaluate_sensor.h, systemc/common/simulate_entry.h, tb/common/cosim_target.h).
// The shipped sensors come from core/sensor_list.h; register_sensor() adds more at run time
// (tests/core/test_fifth_sensor.cpp registers one).
#include <string>
#include <vector>

#include "core/params.h"
#include "core/radiometry.h"
#include "core/scene_rules.h"

namespace rangesim {

struct SensorInfo {
  std::string id;                       // preset id, e.g. "ls-conventional"
  std::string title;                    // one line
  std::string thesis_ref;               // reference number in the thesis, e.g. "[31]"
  const ParamSchema& (*schema)();       // every preset key with its unit, range and meaning
  void (*validate)(const ParamSet& p);  // builds the configuration: throws UserError on cross-key
                                        // inconsistencies, naming the file and both keys
  SceneRules scene = {};                // what its scenes for `rangesim simulate` may hold
  // Its radiometry from a validated preset (core/radiometry.h): how lux and watts of a physical
  // scene become its signal unit. nullptr: the sensor takes no physical scene or axis.
  SensorRadiometry (*radiometry)(const ParamSet& p) = nullptr;
};

// The radiometry of the preset's sensor; throws UserError naming `where` for a sensor without one.
SensorRadiometry radiometry_for(const ParamSet& p, const std::string& where);

// Every registered sensor: the shipped ones in thesis order, then those added at run time.
const std::vector<SensorInfo>& sensors();
const SensorInfo* find_sensor(const std::string& id);

// Adds a sensor (its id must be new: std::invalid_argument otherwise). Pointers returned by
// sensors()/find_sensor() before the call may be invalidated.
void register_sensor(const SensorInfo& info);

// "a, b, c": the registered ids, for messages.
std::string sensor_ids();

// Schema for a sensor id; throws UserError for an unknown id (naming `where`).
const ParamSchema& schema_for(const std::string& sensor_id, const std::string& where);

}  // namespace rangesim
