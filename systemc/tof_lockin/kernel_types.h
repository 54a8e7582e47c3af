#pragma once
// What the tof-lockin clock-level kernels share (thesis [12]; docs/tof-lockin-clock.md): the
// frame phases, the fidelity knobs and a pixel's stimulus. One kernel per block:
//   lockin_gate_generator_kernel.h  gate timing generator (PHASE1/2/3, the light pulse)
//   pixel_kernel.h                  photogate pixel (charge into FD1 / FD2 / drain, noise)
//   column_adc_kernel.h             column ADC (conversion cycles, truncating code)
//   sensor_kernel.h                 readout sequencer + array + ADC, range reconstruction
#include <cstdint>
#include <string>
#include <vector>

#include <pcg_random.hpp>

#include "core/tof_lockin/config.h"

namespace rangesim::systemc::lockin {

// Phases of a frame in schedule order (0 = idle / done).
enum class LockinPhase : int { Idle = 0, Phase1 = 1, Phase2 = 2, Phase3 = 3, AdcConversion = 4, Output = 5 };
const char* phase_name(LockinPhase p);
inline constexpr int kPhaseCount = 5;  // Phase1 .. Output

// Fidelity knobs.
struct LockinSimOptions {
  bool noise = true;           // shot, kTC, read noise on (dark charge is always present
                               // as its mean)
  bool event_skipping = true;  // advance to the next gate edge / conversion end instead of ticking
  bool aggregate = false;      // with event_skipping: one event per accumulation phase (N_acc
                               // identical periods summed; Poisson of the total mean, exact)
  std::uint64_t seed = 1;      // key of the noise streams
  // 0: pulse/gate overlaps in closed form (exact). > 0: the pulse shape integrated numerically
  // at this step (golden::pulse_area_between_s): error falls and cost rises as it shrinks.
  double time_step_s = 0;
};

// Per-pixel stimulus from the scene.
struct LockinPixelStimulus {
  double signal_A = 0;      // signal photocurrent during the received pulse
  double background_A = 0;  // constant background photocurrent
  double delay_s = 0;       // round-trip delay T_D = 2 L / c
};

}  // namespace rangesim::systemc::lockin
