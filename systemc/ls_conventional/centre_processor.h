#pragma once
// Clock-level view of one row's centre processor: a thin sc_module around CentreProcessorKernel
// (which documents the bit-serial protocol and the Q(address_bits).8 output format).
#include <systemc>

#include "systemc/ls_conventional/centre_processor_kernel.h"

namespace rangesim::systemc {

class CentreProcessor : public sc_core::sc_module {
 public:
  sc_core::sc_in<bool> clk_i{"clk_i"};                // rising edge active
  sc_core::sc_in<bool> rst_i{"rst_i"};                // synchronous, active high (clears)
  sc_core::sc_in<bool> clear_i{"clear_i"};            // sequencer reset phase (clears)
  sc_core::sc_in<bool> addr_valid_i{"addr_valid_i"};  // from the row's address search
  sc_core::sc_in<bool> addr_bit_i{"addr_bit_i"};
  sc_core::sc_out<bool> valid_o{"valid_o"};        // some sampling detected
  sc_core::sc_out<unsigned> centre_o{"centre_o"};  // Q(address_bits).8 centre
  sc_core::sc_out<unsigned> sum_o{"sum_o"};        // sum of (left + right)
  sc_core::sc_out<unsigned> count_o{"count_o"};    // detecting samplings

  SC_HAS_PROCESS(CentreProcessor);
  CentreProcessor(sc_core::sc_module_name name, int address_bits);

  const CentreProcessorKernel& kernel() const { return kernel_; }
  CentreProcessorPins pins() const { return kernel_.pins(); }

 private:
  void on_clock();

  CentreProcessorKernel kernel_;  // all state and behaviour
};

}  // namespace rangesim::systemc
