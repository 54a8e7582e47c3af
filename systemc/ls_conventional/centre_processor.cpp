#include "systemc/ls_conventional/centre_processor.h"

namespace rangesim::systemc {

CentreProcessor::CentreProcessor(sc_core::sc_module_name name, int address_bits)
    : sc_core::sc_module(name), kernel_(address_bits) {
  SC_METHOD(on_clock);
  sensitive << clk_i.pos();
  dont_initialize();
  valid_o.initialize(false);
  centre_o.initialize(0);
  sum_o.initialize(0);
  count_o.initialize(0);
}

void CentreProcessor::on_clock() {
  AddressSearchPins in;
  in.addr_valid = addr_valid_i.read();
  in.addr_bit = addr_bit_i.read();
  kernel_.tick(rst_i.read() || clear_i.read(), in);
  const CentreProcessorPins p = kernel_.pins();
  valid_o.write(p.valid);
  centre_o.write(p.centre_q);
  sum_o.write(p.sum);
  count_o.write(static_cast<unsigned>(p.count));
}

}  // namespace rangesim::systemc
