#pragma once
// Clock-level view of the row-parallel part of the ls-conventional readout: every row's address
// search and centre processor (AddressSearchKernel, CentreProcessorKernel), connected as in
// rtl/ls_conventional/ls_conventional_readout.sv and as LsConventionalSensorKernel::tick connects them. The
// per-row sc_modules AddressSearch and CentreProcessor model the same blocks one instance each;
// this module is their array form for the sensor top: one clocked process for all rows and one
// output signal carrying every row's pins (a vector payload), written only when a pin changed.
// 2 x 365 processes and ~7,000 per-row signals and ports cost the scheduler, and SystemC's
// teardown (linear searches per object), more than the kernels they tick.
#include <iosfwd>
#include <string>
#include <systemc>
#include <vector>

#include "core/ls_conventional/config.h"
#include "systemc/common/address_search.h"  // ActivationRow's sc_trace overload (sc_in<ActivationRow>)
#include "systemc/common/address_search_kernel.h"
#include "systemc/ls_conventional/centre_processor_kernel.h"

namespace rangesim::systemc {

// Every row's output pins during one cycle.
struct RowArrayPins {
  std::vector<AddressSearchPins> search;    // per row: the address search's ports
  std::vector<CentreProcessorPins> centre;  // per row: the centre processor's outputs
  bool operator==(const RowArrayPins& o) const { return search == o.search && centre == o.centre; }
};
std::ostream& operator<<(std::ostream& os, const RowArrayPins& p);  // a summary, for SystemC's print()
// sc_signal<RowArrayPins> needs an sc_trace overload; rows are traced one by one instead
// (RowReadoutArray::pins(), see LsConventionalSensor::trace). Found by ADL.
void sc_trace(sc_core::sc_trace_file* tf, const RowArrayPins& pins, const std::string& name);

class RowReadoutArray : public sc_core::sc_module {
 public:
  sc_core::sc_in<bool> clk_i{"clk_i"};                               // rising edge active
  sc_core::sc_in<bool> rst_i{"rst_i"};                               // synchronous, active high
  sc_core::sc_in<bool> start_i{"start_i"};                           // search start strobe (sequencer)
  sc_core::sc_in<bool> clear_i{"clear_i"};                           // centre processors clear (sequencer reset phase)
  sc_core::sc_vector<sc_core::sc_in<ActivationRow>> act_i{"act_i"};  // per row, read at start_i
  sc_core::sc_out<RowArrayPins> pins_o{"pins_o"};                    // every row's pins

  SC_HAS_PROCESS(RowReadoutArray);
  // Throws std::invalid_argument (from the kernels) if the parameters are not buildable.
  RowReadoutArray(sc_core::sc_module_name name, int rows, const AddressSearchConfig& config, int search_cycles);

  // The pins as last written (the value pins_o carries from the next update on). Fixed storage,
  // so its members can be traced by reference (sc_trace of a bool or unsigned).
  const RowArrayPins& pins() const { return out_; }

 private:
  void on_clock();  // one tick of every row's kernels per rising edge

  std::vector<AddressSearchKernel> search_;
  std::vector<CentreProcessorKernel> centre_;
  RowArrayPins out_;
};

}  // namespace rangesim::systemc
