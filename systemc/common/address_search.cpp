#include "systemc/common/address_search.h"

namespace rangesim::systemc {

AddressSearch::AddressSearch(sc_core::sc_module_name name, const AddressSearchConfig& config, int search_cycles)
    : sc_core::sc_module(name), kernel_(config, search_cycles) {
  SC_METHOD(on_clock);
  sensitive << clk_i.pos();
  dont_initialize();
  // Outputs start at the kernel's reset values, like the RTL after reset.
  const AddressSearchPins p = kernel_.pins();
  busy_o.initialize(p.busy);
  found_o.initialize(p.found);
  addr_valid_o.initialize(p.addr_valid);
  addr_bit_o.initialize(p.addr_bit);
  done_o.initialize(p.done);
}

void AddressSearch::on_clock() {
  const bool rst = rst_i.read();
  const bool start = start_i.read();
  // Wrong row width is a testbench error, reported (and counted) instead of asserted.
  if (!rst && start && kernel_.idle() && act_i.read().columns() != kernel_.config().columns) {
    SC_REPORT_ERROR("rangesim/address_search", ("act_i has " + std::to_string(act_i.read().columns()) +
                                                " columns, expected " + std::to_string(kernel_.config().columns))
                                                   .c_str());
    return;
  }
  kernel_.tick(rst, start, act_i.read());
  write_pins();
}

void AddressSearch::write_pins() {
  const AddressSearchPins p = kernel_.pins();
  busy_o.write(p.busy);
  found_o.write(p.found);
  addr_valid_o.write(p.addr_valid);
  addr_bit_o.write(p.addr_bit);
  done_o.write(p.done);
}

void sc_trace(sc_core::sc_trace_file* /*tf*/, const ActivationRow& /*row*/, const std::string& /*name*/) {}

}  // namespace rangesim::systemc
