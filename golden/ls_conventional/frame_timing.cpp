#include "golden/ls_conventional/frame_timing.h"

#include "golden/ls_conventional/model.h"

namespace rangesim::golden {

FrameTiming frame_timing(const FrameTimingConfig& timing, int samplings) {
  FrameTiming t;
  t.samplings = samplings;
  const long long N = samplings;
  // Schedule order: reset once, then per sampling latch -> search -> address stream, then output.
  const std::pair<const char*, long long> phases[] = {
      {"reset", timing.reset_cycles},
      {"latch", N * timing.latch_cycles},
      {"search", N * timing.search_cycles},
      {"address_stream", N * static_cast<long long>(timing.addresses_per_sampling) * timing.address_bits},
      {"output", timing.output_cycles},
  };
  for (const auto& [name, cycles] : phases) t.phases.push_back({name, cycles, cycles / timing.clock_Hz});
  t.frame_cycles = frame_cycles(timing, samplings);
  t.frame_time_s = t.frame_cycles / timing.clock_Hz;
  t.frame_access_rate_Hz = timing.clock_Hz / t.frame_cycles;
  t.range_map_time_s = t.frame_time_s * timing.beam_positions;
  t.range_maps_per_s = t.frame_access_rate_Hz / timing.beam_positions;
  t.clock_Hz = timing.clock_Hz;
  t.frames_per_range_map = timing.beam_positions;
  return t;
}

FrameTiming frame_timing_ls_conventional(const ParamSet& params) {
  const LsConventionalConfig cfg = ls_conventional_from_params(params);
  return frame_timing(cfg.timing, cfg.multisampling.samplings);
}

}  // namespace rangesim::golden
