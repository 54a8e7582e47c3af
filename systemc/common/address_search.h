#pragma once
// Clock-level view of the row address search: a thin sc_module around AddressSearchKernel.
// Ports mirror rtl/common/address_search.sv (same names plus the _i/_o convention for clk/rst), with
// the activation bits as one ActivationRow value instead of a COLUMNS-bit vector, because the
// width is a run-time parameter here. All behaviour is in the kernel.
#include <string>
#include <systemc>

#include "core/ls_conventional/config.h"
#include "systemc/common/address_search_kernel.h"

namespace rangesim::systemc {

class AddressSearch : public sc_core::sc_module {
 public:
  sc_core::sc_in<bool> clk_i{"clk_i"};                 // rising edge active
  sc_core::sc_in<bool> rst_i{"rst_i"};                 // synchronous, active high
  sc_core::sc_in<bool> start_i{"start_i"};             // one-cycle strobe (latch cycle)
  sc_core::sc_in<ActivationRow> act_i{"act_i"};        // latched when start_i is seen
  sc_core::sc_out<bool> busy_o{"busy_o"};              // operation in progress
  sc_core::sc_out<bool> found_o{"found_o"};            // an activated column exists
  sc_core::sc_out<bool> addr_valid_o{"addr_valid_o"};  // addr_bit_o carries an address bit
  sc_core::sc_out<bool> addr_bit_o{"addr_bit_o"};      // left, then right, MSB first
  sc_core::sc_out<bool> done_o{"done_o"};              // last cycle of the operation

  SC_HAS_PROCESS(AddressSearch);
  // Throws std::invalid_argument (from the kernel) if the parameters are not buildable.
  AddressSearch(sc_core::sc_module_name name, const AddressSearchConfig& config,
                int search_cycles = FrameTimingConfig{}.search_cycles);

  const AddressSearchKernel& kernel() const { return kernel_; }

 private:
  void on_clock();    // clocked SC_METHOD: one kernel tick per rising edge
  void write_pins();  // kernel outputs -> ports

  AddressSearchKernel kernel_;  // all state and behaviour
};

// sc_signal<ActivationRow> needs an sc_trace overload to compile. Rows are not traced (their
// width is dynamic); trace the RTL act_i or the kernel's edges instead. Found by ADL.
void sc_trace(sc_core::sc_trace_file* tf, const ActivationRow& row, const std::string& name);

}  // namespace rangesim::systemc
