#pragma once
// Cycle kernel of the ls-demodulation sensor (thesis [27]): plain C++, no SystemC. The composition
// of the demodulating pixel array (demod_pixel_kernel.h), the comparators, the row readout through
// the chained address search (systemc/common/address_search_kernel.h, reused from ls-conventional) with
// the centre (left + right) / 2, and the readout sequencer.
//
// Clock schedule of one frame (golden::frame_timing_ls_demodulation, docs/ls-demodulation-clock.md),
// repeated for each of the K = grid.detections decisions of a frame:
//   integration  W = N clock/f0 cycles: integrators reset at the first edge, all pixels correlate
//                (rows in parallel); MPY+/MPY- and beam edges fall on clock edges
//   decision     1 cycle: every comparator latches D + read offset >= V_cmp
//   row_readout  rows x row_cycles: per row, start the search (1 cycle), chain settle S, stream
//                left and right address (2B bit cycles), idle to row_cycles; S = row_cycles - 1 - 2B
// The frame's per-row position is the mean of the centres of its detecting decisions.
//
// Event skipping: during integration every pixel jumps to the next MPY/beam edge (one exact
// piecewise-exponential step per segment); a row's readout is evaluated in closed form
// (AddressSearchKernel::evaluate). Ticking evaluates every edge. Both give the same cycles and,
// up to floating-point rounding of the analogue values, the same outputs.
// Aggregation (on by default, with event skipping): the N identical correlation periods of a
// window in one jump of W cycles (DemodPixelKernel, golden::correlate_periodic), the shot noise
// one draw per integrator of the exact summed variance: the same cycles, the same noise-free
// outputs to rounding, statistically identical noisy ones. Off, or ticking: period by period.
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/ls_demodulation/config.h"
#include "systemc/common/address_search_kernel.h"
#include "systemc/ls_demodulation/pixel_kernel.h"

namespace rangesim::systemc {

// Light on the array during one frame, row-major [row * columns + column].
struct DemodStimulus {
  std::vector<double> beam_A;               // beam-on photocurrent (square at f0, source duty cycle)
  std::vector<double> background_A;         // constant background photocurrent (dark current added by the pixel)
  std::vector<double> comparator_offset_V;  // each comparator's fixed offset on D (empty: none)
};
using DemodStimulusSource = std::function<void(std::uint64_t frame, DemodStimulus&)>;

struct DemodKernelOptions {
  bool event_skipping = true;  // jump to the next edge (false: tick every cycle)
  bool aggregate = true;       // with event skipping: the N periods of a window in one jump
  std::uint64_t seed = 1;      // key of the noise streams
  DemodNoiseSwitches noise;    // sources on/off
  bool keep_analogue = false;  // keep D of every pixel and decision in the frame result (tests)
};

// Readout of one row in one frame.
struct DemodRowResult {
  int detections = 0;        // decisions of the frame in which the row found an activated pixel
  double centre_sum_px = 0;  // sum of (left + right) / 2 over those decisions
  int left = 0, right = 0;   // addresses streamed by the last detecting decision
  // Extent of the activations over all the frame's detecting decisions (-1: none): what a Monte
  // Carlo trial needs to tell an outlier (an activation outside the spot's pixels) in any decision.
  int min_left = -1, max_right = -1;
  bool valid() const { return detections > 0; }
  double centre_px() const { return detections ? centre_sum_px / detections : 0.0; }
  bool operator==(const DemodRowResult& o) const {
    return detections == o.detections && centre_sum_px == o.centre_sum_px && left == o.left && right == o.right &&
           min_left == o.min_left && max_right == o.max_right;
  }
};

enum class DemodPhase { Integration = 0, Decision = 1, RowReadout = 2, Done = 3 };
const char* to_string(DemodPhase p);

struct DemodFrameResult {
  std::uint64_t frame = 0;
  long long cycles = 0;                    // cycles of this frame
  long long end_cycle = 0;                 // global cycle count at the frame end
  std::vector<long long> phase_cycles;     // integration, decision, row_readout (summed over decisions)
  std::vector<DemodRowResult> rows;        // per row
  std::vector<ActivationRow> activations;  // comparator outputs of the last decision, per row
  std::vector<double> diff_V;  // D per decision, pixel: [(d * rows + row) * columns + col] (keep_analogue only)
  std::vector<double>
      read_offset_V;  // frame-common read noise per decision, row: [d * rows + row] (keep_analogue only)
  int rows_detected() const;
};

// The row search this sensor time-multiplexes over its rows: as wide as the array, two streamed
// addresses, settling for the cycles the row readout leaves (core/ls_demodulation/config.h).
AddressSearchKernel demod_address_search(const LsDemodulationConfig& cfg);

class DemodSensorKernel {
 public:
  // Throws std::invalid_argument naming the key for a configuration it cannot simulate.
  DemodSensorKernel(const LsDemodulationConfig& cfg, const DemodKernelOptions& opt);

  // Starts frame `frame` with its light; the next edge is the first integration edge.
  void start_frame(std::uint64_t frame, const DemodStimulus& stim);
  // One rising clock edge (cycle by cycle; an aggregated window cannot be ticked: throws
  // std::logic_error during its integration, so tick with event skipping or aggregation off).
  void tick();
  // Jumps as far as the switches allow (event skipping: to the next edge that changes state,
  // aggregated: over the whole integration; otherwise one tick); returns the cycles advanced.
  long long advance();
  bool frame_done() const { return phase_ == DemodPhase::Done; }
  // Runs a started frame to its end with advance() and returns its result.
  DemodFrameResult finish_frame();
  DemodFrameResult run_frame(std::uint64_t frame, const DemodStimulus& stim);

  // Pins during the current cycle (what the sc_module drives).
  DemodPhase phase() const { return phase_; }
  int row() const { return row_; }                // row being read out
  bool row_valid() const { return row_strobe_; }  // a row result completed at the last edge
  const DemodRowResult& last_row() const { return last_row_; }
  // Pins of the row search in the current cycle (the address stream; co-simulation compares
  // them with rtl/ls_demodulation/ls_demodulation_sequencer.sv cycle by cycle).
  AddressSearchPins search_pins() const { return search_.pins(); }
  long long cycle() const { return cycle_; }  // edges since construction
  const DemodFrameResult& result() const { return res_; }

  // Read-only views for waveforms (DemodSensor::trace); they do not change the state.
  int decision() const { return decision_; }              // decision index within the frame
  long long phase_cycle() const { return phase_cycle_; }  // cycles done in the current phase (row: in the row)
  bool mpy_plus() const;                                  // integration: MPY+ (C1) selected at this cycle
  const DemodPixelKernel& pixel(int r, int c) const { return pixels_[static_cast<std::size_t>(r) * columns_ + c]; }
  // The comparator output of pixel (r, c) at the last decision (the bit its row search reads).
  bool active(int r, int c) const {
    const auto row = static_cast<std::size_t>(r);
    return row < res_.activations.size() && res_.activations[row].test(c);
  }

  const LsDemodulationConfig& config() const { return cfg_; }
  const DemodWindowSchedule& schedule() const { return sched_; }
  int search_cycles() const { return search_cycles_; }
  long long frame_cycles() const;  // the schedule's frame length

 private:
  void begin_decision();
  void decide();
  void finish_row(const AddressSearchResult& r);
  void enter_row(int row);

  LsDemodulationConfig cfg_;              // sensor parameters
  DemodKernelOptions opt_;                // harness switches
  DemodWindowSchedule sched_;             // integration schedule
  int rows_ = 0, columns_ = 0;            // array size
  int search_cycles_ = 0;                 // chain settle S of the row search
  std::vector<DemodPixelKernel> pixels_;  // row-major
  std::vector<pcg32> rngs_;               // per pixel stream of the current decision
  AddressSearchKernel search_;            // the row search (one, time-multiplexed over the rows)
  DemodStimulus stim_;                    // light of the current frame
  DemodFrameResult res_;                  // result being built
  DemodPhase phase_ = DemodPhase::Done;   // sequencer state
  int decision_ = 0;                      // decision index within the frame
  long long phase_cycle_ = 0;             // cycles done in the current phase / row
  int row_ = 0;                           // row being read out
  std::uint64_t bits_ = 0;                // streamed address bits of the row
  bool row_strobe_ = false;               // a row result completed at the last edge
  DemodRowResult last_row_;               // the last completed row's result
  long long cycle_ = 0;                   // global edge count
};

// Bounded run of `frames` frames on the bare kernel (cycle budget = frames x frame_cycles).
struct DemodRunResult {
  std::vector<DemodFrameResult> frames;
  long long cycles = 0;
  double simulated_time_s = 0;  // cycles / clock (kernel) or sc_time_stamp (SystemC)
  double wall_time_s = 0;
  long long sc_errors = 0;  // SystemC harness only
};
// Called after each finished frame with the number of frames done (progress reports).
using DemodProgress = std::function<void(long long frames_done)>;
DemodRunResult run_demod_kernel(const LsDemodulationConfig& cfg, const DemodKernelOptions& opt,
                                const DemodStimulusSource& source, long long frames,
                                const DemodProgress& progress = {});

}  // namespace rangesim::systemc
