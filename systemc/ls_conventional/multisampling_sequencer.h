#pragma once
// Clock-level view of the readout sequencer: a thin sc_module around MultisamplingSequencerKernel
// (systemc/ls_conventional/multisampling_sequencer_kernel.h has the schedule). All behaviour is in the kernel.
#include <systemc>

#include "core/ls_conventional/config.h"
#include "systemc/ls_conventional/multisampling_sequencer_kernel.h"

namespace rangesim::systemc {

class MultisamplingSequencer : public sc_core::sc_module {
 public:
  sc_core::sc_in<bool> clk_i{"clk_i"};                     // rising edge active
  sc_core::sc_in<bool> rst_i{"rst_i"};                     // synchronous, active high
  sc_core::sc_out<bool> pix_reset_o{"pix_reset_o"};        // reset phase: pixels reset, centres cleared
  sc_core::sc_out<bool> latch_o{"latch_o"};                // comparator latch phase
  sc_core::sc_out<bool> search_start_o{"search_start_o"};  // start strobe of the row searches
  sc_core::sc_out<bool> frame_done_o{"frame_done_o"};      // last cycle of a frame access
  sc_core::sc_out<unsigned> phase_o{"phase_o"};            // ReadoutPhase as a number (for waveforms)
  sc_core::sc_out<unsigned> sampling_o{"sampling_o"};      // k during sampling k, else 0
  sc_core::sc_out<sc_dt::uint64> frame_o{"frame_o"};       // frame-access counter

  SC_HAS_PROCESS(MultisamplingSequencer);
  // Throws std::invalid_argument (from the kernel) for a schedule that cannot run.
  MultisamplingSequencer(sc_core::sc_module_name name, const FrameTimingConfig& timing, int samplings);

  const MultisamplingSequencerKernel& kernel() const { return kernel_; }
  // The pins as the kernel has them (the ports carry the same values one delta later).
  MultisamplingSequencerPins pins() const { return kernel_.pins(); }

 private:
  void on_clock();
  void write_pins();

  MultisamplingSequencerKernel kernel_;  // all state and behaviour
};

}  // namespace rangesim::systemc
