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

enum class PoissonTables { Never, WhenTheyPay, Always };

// Fidelity knobs.
struct LockinSimOptions {
  bool noise = true;           // shot, kTC, read noise on (dark charge is always present
                               // as its mean)
  bool event_skipping = true;  // advance to the next gate edge / conversion end instead of ticking
  bool aggregate = false;      // with event_skipping: one event per accumulation phase (N_acc
                               // identical periods summed; Poisson of the total mean, exact)
  std::uint64_t seed = 1;      // key of the noise streams
  // Merged draws of aggregated frames (config simulation.merged_draws): counts of a mean from its
  // alias table where the kernel draws that mean often enough to pay for the table (frame_draw.h),
  // else by PTRS; or always (a Monte Carlo point's trials), or never.
  PoissonTables poisson_tables = PoissonTables::WhenTheyPay;
  // 0: pulse/gate overlaps in closed form (exact). > 0: the pulse shape integrated numerically
  // at this step (golden::pulse_area_between_s): error falls and cost rises as it shrinks.
  double time_step_s = 0;
};

// A further return of the pulse on a pixel (multipath; a neighbour's surface by the point spread).
struct LockinEcho {
  double signal_A = 0;  // photocurrent during the received pulse
  double delay_s = 0;   // its round-trip delay
};

// Per-pixel stimulus from the scene (and the chip's fixed pattern, systemc/tof_lockin/nonideal_stimulus.h).
struct LockinPixelStimulus {
  double signal_A = 0;                  // signal photocurrent during the received pulse
  double background_A = 0;              // constant background photocurrent
  double delay_s = 0;                   // round-trip delay T_D = 2 L / c
  std::vector<LockinEcho> echoes = {};  // further returns, each like signal_A at its own delay (usually none)
  double tap_gain[2] = {1, 1};          // fixed pattern: relative charge gain of FD1 / FD2
  double dark_extra_A[2] = {0, 0};      // fixed pattern: this pixel's dark current minus the mean, per FD
};

}  // namespace rangesim::systemc::lockin
