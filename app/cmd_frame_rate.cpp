// rangesim frame-rate: frame time from the clock schedule, by phase, and the rates.
#include <fmt/format.h>
#include <nlohmann/json.hpp>

#include "app/cli_common.h"
#include "app/commands.h"
#include "core/ls_conventional_config.h"
#include "core/preset.h"
#include "golden/frame_timing.h"

namespace rangesim::app {

nlohmann::json frame_timing_json(const golden::FrameTiming& t, const FrameTimingConfig& cfg) {
  nlohmann::json phases = nlohmann::json::array();
  for (const auto& p : t.phases) phases.push_back({{"name", p.name}, {"cycles", p.cycles}, {"time_s", p.time_s}});
  return {{"samplings", t.samplings},
          {"clock_Hz", cfg.clock_Hz},
          {"frame_cycles", t.frame_cycles},
          {"frame_time_s", t.frame_time_s},
          {"frame_access_rate_Hz", t.frame_access_rate_Hz},
          {"beam_positions", cfg.beam_positions},
          {"range_map_time_s", t.range_map_time_s},
          {"range_maps_per_s", t.range_maps_per_s},
          {"phases", phases}};
}

int run_frame_rate(const FrameRateOptions& opt) {
  ParamSet params = load_modelled_preset(opt.sensor, "frame-rate");
  const ParamSchema& schema = schema_for(params.sensor_id(), params.origin());
  if (opt.samplings) params.set_integer("multisampling.samplings", *opt.samplings, "--samplings", schema);
  const LsConventionalConfig cfg = ls_conventional_from_params(params);
  const golden::FrameTiming t = golden::frame_timing(cfg.timing, cfg.multisampling.samplings);

  if (opt.json) {
    nlohmann::json j = frame_timing_json(t, cfg.timing);
    j["sensor"] = params.sensor_id();
    j["preset"] = params.origin();
    fmt::print("{}\n", j.dump(2));
    return 0;
  }
  fmt::print("{}: frame access with {} sampling{} at {:g} MHz\n\n", params.sensor_id(), t.samplings,
             t.samplings == 1 ? "" : "s", cfg.timing.clock_Hz / 1e6);
  fmt::print("  {:<16} {:>8} {:>12}\n", "phase", "cycles", "time");
  for (const auto& p : t.phases) fmt::print("  {:<16} {:>8} {:>9.2f} ns\n", p.name, p.cycles, p.time_s * 1e9);
  fmt::print("  {:<16} {:>8} {:>9.2f} ns\n\n", "frame access", t.frame_cycles, t.frame_time_s * 1e9);
  fmt::print("  frame access rate  {:>12.2f} kHz\n", t.frame_access_rate_Hz / 1e3);
  fmt::print("  range map          {:>12.3f} ms  ({} frame accesses, one per beam position)\n",
             t.range_map_time_s * 1e3, cfg.timing.beam_positions);
  fmt::print("  range maps         {:>12.2f} /s\n", t.range_maps_per_s);
  return 0;
}

}  // namespace rangesim::app
