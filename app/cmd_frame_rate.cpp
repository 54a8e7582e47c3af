// rangesim frame-rate: frame time from the clock schedule, by phase, and the rates.
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "app/cli_common.h"
#include "app/command_data.h"
#include "app/commands.h"
#include "core/preset.h"
#include "core/user_error.h"
#include "golden/common/evaluate_sensor.h"
#include "golden/common/frame_timing.h"

namespace rangesim::app {

nlohmann::json frame_timing_json(const golden::FrameTiming& t) {
  nlohmann::json phases = nlohmann::json::array();
  for (const auto& p : t.phases) phases.push_back({{"name", p.name}, {"cycles", p.cycles}, {"time_s", p.time_s}});
  return {{"samplings", t.samplings},
          {"clock_Hz", t.clock_Hz},
          {"frame_cycles", t.frame_cycles},
          {"frame_time_s", t.frame_time_s},
          {"frame_access_rate_Hz", t.frame_access_rate_Hz},
          {"frames_per_range_map", t.frames_per_range_map},
          {"range_map_time_s", t.range_map_time_s},
          {"range_maps_per_s", t.range_maps_per_s},
          {"phases", phases}};
}

void apply_frame_rate_samplings(ParamSet& params, int samplings) {
  const ParamSchema& schema = schema_for(params.sensor_id(), params.origin());
  if (!schema.find("multisampling.samplings"))
    throw UserError(fmt::format("--samplings: sensor {} has no samplings parameter (see `rangesim show {}`)",
                                params.sensor_id(), params.sensor_id()),
                    "samplings");
  params.set_integer("multisampling.samplings", samplings, "--samplings", schema);
}

nlohmann::json frame_rate_json(const ParamSet& params) {
  nlohmann::json j = frame_timing_json(golden::frame_timing_for(params));
  j["sensor"] = params.sensor_id();
  j["preset"] = params.origin();
  return j;
}

int run_frame_rate(const FrameRateOptions& opt) {
  ParamSet params = load_modelled_preset(opt.sensor, "frame-rate", opt.settings);
  if (opt.samplings) apply_frame_rate_samplings(params, *opt.samplings);
  if (opt.json) {
    fmt::print("{}\n", frame_rate_json(params).dump(2));
    return 0;
  }
  const golden::FrameTiming t = golden::frame_timing_for(params);
  const bool ls = params.sensor_id().rfind("ls-", 0) == 0;
  fmt::print("{}: {}{} at {:g} MHz\n\n", params.sensor_id(), ls ? "frame access" : "frame",
             ls && t.samplings > 0 ? fmt::format(" with {} sampling{}", t.samplings, t.samplings == 1 ? "" : "s") : "",
             t.clock_Hz / 1e6);
  // Times in the unit that suits the frame: ns for ls-conventional's 2.5 us, s for a SPAD frame.
  const double scale = t.frame_time_s < 1e-5 ? 1e9 : t.frame_time_s < 1e-2 ? 1e6 : t.frame_time_s < 10 ? 1e3 : 1;
  const char* unit = scale == 1e9 ? "ns" : scale == 1e6 ? "us" : scale == 1e3 ? "ms" : "s";
  fmt::print("  {:<18} {:>14} {:>14}\n", "phase", "cycles", "time");
  for (const auto& p : t.phases) fmt::print("  {:<18} {:>14} {:>11.3f} {}\n", p.name, p.cycles, p.time_s * scale, unit);
  fmt::print("  {:<18} {:>14} {:>11.3f} {}\n\n", ls ? "frame access" : "frame", t.frame_cycles, t.frame_time_s * scale,
             unit);
  fmt::print("  {:<18} {:>14.3f} Hz\n", ls ? "frame access rate" : "frame rate", t.frame_access_rate_Hz);
  fmt::print("  {:<18} {:>14.6f} s  ({} frame{} per range map)\n", "range map", t.range_map_time_s,
             t.frames_per_range_map, t.frames_per_range_map == 1 ? "" : "s");
  fmt::print("  {:<18} {:>14.3f} /s\n", "range maps", t.range_maps_per_s);
  return 0;
}

}  // namespace rangesim::app
