#include "systemc/ls_conventional/multisampling_sequencer.h"

namespace rangesim::systemc {

MultisamplingSequencer::MultisamplingSequencer(sc_core::sc_module_name name, const FrameTimingConfig& timing,
                                               int samplings)
    : sc_core::sc_module(name), kernel_(timing, samplings) {
  SC_METHOD(on_clock);
  sensitive << clk_i.pos();
  dont_initialize();
  kernel_.tick(true);  // outputs start as after reset: frame 0, cycle 0 (reset phase)
  const MultisamplingSequencerPins p = kernel_.pins();
  pix_reset_o.initialize(p.pix_reset);
  latch_o.initialize(p.latch);
  search_start_o.initialize(p.search_start);
  frame_done_o.initialize(p.frame_done);
  phase_o.initialize(static_cast<unsigned>(p.phase));
  sampling_o.initialize(static_cast<unsigned>(p.sampling));
  frame_o.initialize(p.frame);
}

void MultisamplingSequencer::on_clock() {
  kernel_.tick(rst_i.read());
  write_pins();
}

void MultisamplingSequencer::write_pins() {
  const MultisamplingSequencerPins p = kernel_.pins();
  pix_reset_o.write(p.pix_reset);
  latch_o.write(p.latch);
  search_start_o.write(p.search_start);
  frame_done_o.write(p.frame_done);
  phase_o.write(static_cast<unsigned>(p.phase));
  sampling_o.write(static_cast<unsigned>(p.sampling));
  frame_o.write(p.frame);
}

}  // namespace rangesim::systemc
