#pragma once
// Thin sc_module around the ls-demodulation sensor kernel (demod_sensor_kernel.h): one clocked
// SC_METHOD ticks the kernel at every rising edge and drives its pins; the kernel holds all state.
// With event skipping on (DemodKernelOptions) the method lets the kernel jump to its next edge
// and sleeps until then (next_trigger), so simulated time still advances edge-exactly.
// It also checks each frame's length against the schedule (SC_REPORT_ERROR on a mismatch).
#include <cstdint>
#include <string>
#include <memory>
#include <systemc>

#include "systemc/common/simulate_entry.h"
#include "systemc/common/waveform.h"

#include "systemc/ls_demodulation/sensor_kernel.h"

namespace rangesim::systemc {

class DemodSensor : public sc_core::sc_module {
 public:
  sc_core::sc_in<bool> clk_i{"clk_i"};                         // readout clock
  sc_core::sc_out<int> phase_o{"phase_o"};                     // DemodPhase of the current cycle
  sc_core::sc_out<int> row_o{"row_o"};                         // row being read out
  sc_core::sc_out<bool> row_valid_o{"row_valid_o"};            // a row's search completed at this edge
  sc_core::sc_out<int> row_detections_o{"row_detections_o"};   // detections of that row so far
  sc_core::sc_out<double> row_centre_px_o{"row_centre_px_o"};  // its mean centre (when detections > 0)
  sc_core::sc_out<bool> frame_done_o{"frame_done_o"};          // the last edge of a frame
  // Waveform pins (--trace): the sequencer's counters, the correlator gate and the row search.
  sc_core::sc_out<int> frame_o{"frame_o"};              // frame index (beam position)
  sc_core::sc_out<int> decision_o{"decision_o"};        // decision index within the frame
  sc_core::sc_out<int> phase_cycle_o{"phase_cycle_o"};  // cycle counter within the phase (row readout: within the row)
  sc_core::sc_out<bool> mpy_plus_o{"mpy_plus_o"};       // correlator gate: MPY+ (C1) integrates; MPY- otherwise
  sc_core::sc_out<bool> search_start_o{"search_start_o"};  // strobe: a row search starts
  sc_core::sc_out<bool> addr_valid_o{"addr_valid_o"};      // bit-serial address stream: bit valid
  sc_core::sc_out<bool> addr_bit_o{"addr_bit_o"};          // ... the bit (left address, then right, MSB first)

  SC_HAS_PROCESS(DemodSensor);
  // Runs `frames` frames from `source`, then calls sc_stop().
  DemodSensor(sc_core::sc_module_name name, const LsDemodulationConfig& cfg, const DemodKernelOptions& opt,
              DemodStimulusSource source, long long frames, DemodProgress progress = {});

  const std::vector<DemodFrameResult>& frames() const { return results_; }
  long long edges() const { return kernel_.cycle(); }
  long long frame_cycles() const { return kernel_.frame_cycles(); }
  sc_core::sc_time span_end() const { return span_end_; }  // end of the last clock cycle simulated
  // Adds the clock and every pin to a trace file (call before sc_start). With event skipping the
  // pins change only at the edges the kernel stops at; --tick shows every address bit.
  // `pixels`: each one's correlator outputs V_out+ and V_out- (ls_demodulation.pixel_<r>_<c>).
  void trace(Waveform& w, const std::vector<TracePixel>& pixels = {});  // scopes ls_demodulation.{sequencer,readout}

 private:
  void on_clock();

  DemodSensorKernel kernel_;               // all state
  DemodStimulusSource source_;             // light per frame
  DemodProgress progress_;                 // called after each frame (may be empty)
  long long frames_;                       // frames to run
  std::vector<DemodFrameResult> results_;  // finished frames
  DemodStimulus stim_;                     // stimulus buffer
  bool event_skipping_;                    // jump edges (advance) or tick every edge
  sc_core::sc_time period_;                // clock period
  sc_core::sc_time span_end_;              // end of the last cycle the kernel has simulated
  struct PixelProbe {
    TracePixel at;
    std::unique_ptr<double[]> out_V;  // V_out+, V_out- (traced by reference: fixed storage)
    std::unique_ptr<bool> active;     // the comparator output latched at the last decision
  };
  std::vector<PixelProbe> pixel_probes_;  // traced pixels (updated at every edge the kernel stops at)
};

// Elaborates a clock and DemodSensor, runs `frames` frames (bounded by a time budget of one frame
// more) and returns the frames, cycles, simulated time (edges x clock period) and SC_ERROR count.
// One elaboration per process.
// `vcd_base` non-empty: writes a VCD waveform to vcd_base + ".vcd". `progress` is called after
// each finished frame.
DemodRunResult run_demod_systemc(const LsDemodulationConfig& cfg, const DemodKernelOptions& opt,
                                 const DemodStimulusSource& source, long long frames, const std::string& vcd_base = "",
                                 const DemodProgress& progress = {}, const std::vector<TracePixel>& traced = {});

}  // namespace rangesim::systemc
