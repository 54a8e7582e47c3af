// Frame timing of tof-lockin from its clock schedule
// (docs/tof-lockin-clock.md).
//
// One frame (LED frame or ambient frame, same schedule) is:
//   accumulation: N_acc periods of T_rep = T0 / duty gate-clock cycles, each
//   PHASE1 (TX1, T0
//                 cycles), PHASE2 (TX2, T0 cycles), PHASE3 (TXD, T_rep - 2 T0
//                 cycles); cycles counted at gates.clock_Hz;
//   readout:      per row, one column-parallel ADC conversion of both FDs
//   (adc_conversion_cycles)
//                 then the row is shifted out (output_cycles_per_row); rows one
//                 after the other; cycles counted at readout.clock_Hz.
//   frame_time_s = N_acc T_rep_cycles / f_gate + rows (conv + out) / f_readout
// Phases: "phase1", "phase2", "phase3" (summed over N_acc, gate-clock cycles),
// "adc_conversion", "output" (summed over rows, readout-clock cycles).
// frame_cycles is the sum over the phases, each in its own clock (clock_Hz =
// the gate clock; the readout phases' time_s uses the readout clock). A range
// map is 2 frames with readout.ambient_subtraction (LED frame + ambient frame),
// else 1.
#include <algorithm>
#include <cmath>
#include <fmt/format.h>

#include "core/tof_lockin/config.h"
#include "core/user_error.h"
#include "golden/common/evaluate_sensor.h"
#include "golden/tof_lockin/model.h"

namespace rangesim::golden {

FrameTiming frame_timing_tof_lockin(const ParamSet& params) {
  const TofLockinConfig cfg = tof_lockin_from_params(params);
  const double fg = cfg.gates.clock_Hz, fr = cfg.readout.clock_Hz;
  const long long t0 = std::llround(cfg.source.pulse_width_s * fg);  // whole cycles (config checks it)
  const double period_exact = cfg.source.pulse_width_s / cfg.source.duty_cycle * fg;
  const long long period = std::llround(period_exact);
  // The clock schedule needs T_rep = T0 / duty on the gate-clock grid too (same
  // rule as the clock-level gate generator,
  // systemc/tof_lockin/lockin_gate_generator_kernel.cpp).
  if (std::fabs(period_exact - static_cast<double>(period)) > 1e-6 * std::max(1.0, period_exact))
    throw UserError(
        fmt::format("{}: source.pulse_width_s / source.duty_cycle = {:g} s is {:g} cycles "
                    "of gates.clock_Hz = "
                    "{:g}; allowed for the clock schedule: a whole number of gate-clock "
                    "cycles",
                    params.origin(), cfg.source.pulse_width_s / cfg.source.duty_cycle, period_exact, fg));
  const long long n = cfg.gates.accumulations_per_frame;
  const long long rows = cfg.pixel.rows;
  FrameTiming t;
  t.clock_Hz = fg;
  t.phases.push_back({"phase1", n * t0, static_cast<double>(n * t0) / fg});
  t.phases.push_back({"phase2", n * t0, static_cast<double>(n * t0) / fg});
  t.phases.push_back({"phase3", n * (period - 2 * t0), static_cast<double>(n * (period - 2 * t0)) / fg});
  t.phases.push_back({"adc_conversion", rows * cfg.readout.adc_conversion_cycles,
                      static_cast<double>(rows * cfg.readout.adc_conversion_cycles) / fr});
  t.phases.push_back({"output", rows * cfg.readout.output_cycles_per_row,
                      static_cast<double>(rows * cfg.readout.output_cycles_per_row) / fr});
  const long long acc_cycles = n * period;
  const long long ro_cycles = rows * (cfg.readout.adc_conversion_cycles + cfg.readout.output_cycles_per_row);
  t.frame_cycles = acc_cycles + ro_cycles;
  t.frame_time_s = static_cast<double>(acc_cycles) / fg + static_cast<double>(ro_cycles) / fr;
  t.frame_access_rate_Hz = 1.0 / t.frame_time_s;
  t.frames_per_range_map = cfg.readout.ambient_subtraction ? 2 : 1;
  t.range_map_time_s = t.frame_time_s * static_cast<double>(t.frames_per_range_map);
  t.range_maps_per_s = 1.0 / t.range_map_time_s;
  t.samplings = 0;
  return t;
}

}  // namespace rangesim::golden
