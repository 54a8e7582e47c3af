#pragma once
// Clock-level view of the row-parallel part of the ls-conventional readout: every row's address
// search and centre processor (AddressSearchKernel, CentreProcessorKernel), connected as in
// rtl/ls_conventional_readout.sv and as LsConventionalSensorKernel::tick connects them. The
// per-row sc_modules AddressSearch and CentreProcessor model the same blocks one instance each;
// this module is their array form for the sensor top: one clocked process for all rows (730
// per-row processes cost more than the kernels they tick), and an output signal is written only
// when its value changes. Ports per row are sc_vectors, so rows can still be traced one by one.
#include <systemc>
#include <vector>

#include "core/ls_conventional_config.h"
#include "systemc/address_search.h"  // ActivationRow's sc_trace overload (sc_in<ActivationRow>)
#include "systemc/address_search_kernel.h"
#include "systemc/centre_processor_kernel.h"

namespace rangesim::systemc {

class RowReadoutArray : public sc_core::sc_module {
 public:
  sc_core::sc_in<bool> clk_i{"clk_i"};      // rising edge active
  sc_core::sc_in<bool> rst_i{"rst_i"};      // synchronous, active high
  sc_core::sc_in<bool> start_i{"start_i"};  // search start strobe (sequencer)
  sc_core::sc_in<bool> clear_i{"clear_i"};  // centre processors clear (sequencer reset phase)
  sc_core::sc_vector<sc_core::sc_in<ActivationRow>> act_i{"act_i"};  // per row, read at start_i
  // Per row: the address search's pins and the centre processor's outputs.
  sc_core::sc_vector<sc_core::sc_out<bool>> busy_o{"busy_o"}, found_o{"found_o"}, addr_valid_o{"addr_valid_o"},
      addr_bit_o{"addr_bit_o"}, done_o{"done_o"}, centre_valid_o{"centre_valid_o"};
  sc_core::sc_vector<sc_core::sc_out<unsigned>> centre_o{"centre_o"}, sum_o{"sum_o"}, count_o{"count_o"};

  SC_HAS_PROCESS(RowReadoutArray);
  // Throws std::invalid_argument (from the kernels) if the parameters are not buildable.
  RowReadoutArray(sc_core::sc_module_name name, int rows, const AddressSearchConfig& config, int search_cycles);

  const AddressSearchKernel& search(int row) const { return search_[static_cast<std::size_t>(row)]; }
  const CentreProcessorKernel& centre(int row) const { return centre_[static_cast<std::size_t>(row)]; }

 private:
  void on_clock();  // one tick of every row's kernels per rising edge

  std::vector<AddressSearchKernel> search_;
  std::vector<CentreProcessorKernel> centre_;
  std::vector<AddressSearchPins> search_out_;    // per row: as last written
  std::vector<CentreProcessorPins> centre_out_;  // per row: as last written
};

}  // namespace rangesim::systemc
