#pragma once
// Clock-level view of the pixel array with its comparators: a thin sc_module around
// PixelArrayKernel. The array has no clock of its own here: it follows the readout sequencer's
// registered control pins combinationally (a complete-sensitivity SC_METHOD), so that the latched
// activation rows are on act_o during the latch cycle in which the row searches take them.
#include <systemc>

#include "core/ls_conventional/config.h"
#include "systemc/common/address_search.h"  // ActivationRow and its sc_trace overload (for sc_out<ActivationRow>)
#include "systemc/ls_conventional/frame_stimulus.h"
#include "systemc/ls_conventional/pixel_array_kernel.h"

namespace rangesim::systemc {

class PixelArray : public sc_core::sc_module {
 public:
  sc_core::sc_in<bool> pix_reset_i{"pix_reset_i"};                    // reset phase of a frame access
  sc_core::sc_in<unsigned> sampling_i{"sampling_i"};                  // k >= 1: latch the comparators at t_k
  sc_core::sc_in<sc_dt::uint64> frame_i{"frame_i"};                   // frame access (stimulus and noise key)
  sc_core::sc_vector<sc_core::sc_out<ActivationRow>> act_o{"act_o"};  // latched activations per row

  SC_HAS_PROCESS(PixelArray);
  PixelArray(sc_core::sc_module_name name, const LsConventionalConfig& config, const PixelArrayOptions& options,
             StimulusSource source);

  const PixelArrayKernel& kernel() const { return kernel_; }

 private:
  void on_control();  // combinational: control pins -> kernel -> act_o

  PixelArrayKernel kernel_;  // all state and behaviour
};

}  // namespace rangesim::systemc
