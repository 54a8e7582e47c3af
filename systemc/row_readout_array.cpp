#include "systemc/row_readout_array.h"

#include <string>

namespace rangesim::systemc {

RowReadoutArray::RowReadoutArray(sc_core::sc_module_name name, int rows, const AddressSearchConfig& config,
                                 int search_cycles)
    : sc_core::sc_module(name) {
  const std::size_t n = static_cast<std::size_t>(rows);
  search_.reserve(n);
  centre_.reserve(n);
  for (std::size_t r = 0; r < n; ++r) {
    search_.emplace_back(config, search_cycles);
    centre_.emplace_back(config.address_bits);
  }
  act_i.init(n);
  for (auto* v : {&busy_o, &found_o, &addr_valid_o, &addr_bit_o, &done_o, &centre_valid_o}) v->init(n);
  for (auto* v : {&centre_o, &sum_o, &count_o}) v->init(n);
  // Outputs start at the kernels' reset values, like the RTL after reset.
  search_out_.assign(n, search_[0].pins());
  centre_out_.assign(n, centre_[0].pins());
  for (std::size_t r = 0; r < n; ++r) {
    const AddressSearchPins& s = search_out_[r];
    busy_o[r].initialize(s.busy);
    found_o[r].initialize(s.found);
    addr_valid_o[r].initialize(s.addr_valid);
    addr_bit_o[r].initialize(s.addr_bit);
    done_o[r].initialize(s.done);
    const CentreProcessorPins& c = centre_out_[r];
    centre_valid_o[r].initialize(c.valid);
    centre_o[r].initialize(c.centre_q);
    sum_o[r].initialize(c.sum);
    count_o[r].initialize(static_cast<unsigned>(c.count));
  }
  SC_METHOD(on_clock);
  sensitive << clk_i.pos();
  dont_initialize();
}

void RowReadoutArray::on_clock() {
  const bool rst = rst_i.read(), start = start_i.read(), clear = rst || clear_i.read();
  static const ActivationRow kNone;
  for (std::size_t r = 0; r < search_.size(); ++r) {
    AddressSearchKernel& s = search_[r];
    // The centre processor reads the search's pins of the ending cycle: as last written.
    const AddressSearchPins in = search_out_[r];
    const bool latch = !rst && start && s.idle();
    const ActivationRow& act = latch ? act_i[r].read() : kNone;  // read only where the search takes it
    if (latch && act.columns() != s.config().columns)  // a testbench error, reported as in AddressSearch
      SC_REPORT_ERROR("rangesim/row_readout_array", ("row " + std::to_string(r) + ": act_i has " +
                                                     std::to_string(act.columns()) + " columns, expected " +
                                                     std::to_string(s.config().columns))
                                                        .c_str());
    else
      s.tick(rst, start, act);
    centre_[r].tick(clear, in);
    // Write only what changed: most pins of most rows hold for most cycles.
    const AddressSearchPins p = s.pins();
    AddressSearchPins& po = search_out_[r];
    if (!(p == po)) {
      if (p.busy != po.busy) busy_o[r].write(p.busy);
      if (p.found != po.found) found_o[r].write(p.found);
      if (p.addr_valid != po.addr_valid) addr_valid_o[r].write(p.addr_valid);
      if (p.addr_bit != po.addr_bit) addr_bit_o[r].write(p.addr_bit);
      if (p.done != po.done) done_o[r].write(p.done);
      po = p;
    }
    const CentreProcessorPins c = centre_[r].pins();
    CentreProcessorPins& co = centre_out_[r];
    if (c != co) {
      if (c.valid != co.valid) centre_valid_o[r].write(c.valid);
      if (c.centre_q != co.centre_q) centre_o[r].write(c.centre_q);
      if (c.sum != co.sum) sum_o[r].write(c.sum);
      if (c.count != co.count) count_o[r].write(static_cast<unsigned>(c.count));
      co = c;
    }
  }
}

}  // namespace rangesim::systemc
