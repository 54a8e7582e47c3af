// Frame timing of ls-demodulation from the clock schedule of its clock-level model
// (systemc/ls_demodulation/sensor_kernel.h, docs/ls-demodulation-clock.md).
//
// One frame (one sheet-beam position) is, for each of the K = evaluation.detections decisions:
//   integration  W = N x clock / f0 cycles (N = correlator.cycles periods; integrators reset at the
//                first edge, all rows correlate in parallel)
//   decision     1 cycle (every comparator latches D >= V_cmp)
//   row_readout  rows x row_cycles (per row: search start, chain settle S = row_cycles - 1 - 2B,
//                bit-serial left and right address, 2B cycles; rows one after another)
//   frame_cycles = K (W + 1 + rows x row_cycles)
// frame_time_s = frame_cycles / clock, frame_access_rate_Hz = 1 / frame_time_s (frames per second).
// A range map is one frame per beam position; the sheet beam steps one pixel column per frame, so
// frames_per_range_map = pixel.columns.
// Preset: W = 5 x 100 = 500, 110 x 41 = 4510: 5011 cycles at 10 MHz = 501.1 us, 1995.6 fps
// (golden::demod_frame_time_s, which leaves out the decision cycle, gives 501.0 us).
#include <cmath>
#include <stdexcept>

#include "core/ls_demodulation/config.h"
#include "golden/common/evaluate_sensor.h"
#include "golden/common/frame_timing.h"
#include "golden/ls_demodulation/model.h"

namespace rangesim::golden {

FrameTiming frame_timing_ls_demodulation(const ParamSet& params) {
  const LsDemodulationConfig cfg = ls_demodulation_from_params(params);
  const double clock = cfg.readout.clock_Hz;
  const long long K = cfg.grid.detections;
  const long long period = std::llround(clock / cfg.modulation.frequency_Hz);
  const long long W = period * cfg.correlator.cycles;
  const long long readout = static_cast<long long>(cfg.pixel.rows) * cfg.readout.row_cycles;
  FrameTiming t;
  t.clock_Hz = clock;
  t.samplings = static_cast<int>(K);
  t.phases = {{"integration", K * W, K * W / clock},
              {"decision", K, K / clock},
              {"row_readout", K * readout, K * readout / clock}};
  for (const auto& p : t.phases) t.frame_cycles += p.cycles;
  t.frame_time_s = t.frame_cycles / clock;
  t.frame_access_rate_Hz = 1.0 / t.frame_time_s;
  t.frames_per_range_map = cfg.pixel.columns;
  t.range_map_time_s = t.frame_time_s * t.frames_per_range_map;
  t.range_maps_per_s = 1.0 / t.range_map_time_s;
  return t;
}

}  // namespace rangesim::golden
