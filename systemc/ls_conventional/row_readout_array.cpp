#include "systemc/ls_conventional/row_readout_array.h"

#include <ostream>
#include <string>

namespace rangesim::systemc {

std::ostream& operator<<(std::ostream& os, const RowArrayPins& p) {
  int busy = 0, valid = 0;
  for (const auto& s : p.search) busy += s.busy;
  for (const auto& c : p.centre) valid += c.valid;
  return os << p.search.size() << " rows, " << busy << " busy, " << valid << " centres valid";
}

void sc_trace(sc_core::sc_trace_file* /*tf*/, const RowArrayPins& /*pins*/, const std::string& /*name*/) {}

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
  // Outputs start at the kernels' reset values, like the RTL after reset.
  out_.search.assign(n, search_[0].pins());
  out_.centre.assign(n, centre_[0].pins());
  pins_o.initialize(out_);
  SC_METHOD(on_clock);
  sensitive << clk_i.pos();
  dont_initialize();
}

void RowReadoutArray::on_clock() {
  const bool rst = rst_i.read(), start = start_i.read(), clear = rst || clear_i.read();
  static const ActivationRow kNone;
  bool changed = false;
  for (std::size_t r = 0; r < search_.size(); ++r) {
    AddressSearchKernel& s = search_[r];
    AddressSearchPins& so = out_.search[r];
    // The centre processor reads the search's pins of the ending cycle: as last written.
    const AddressSearchPins in = so;
    const bool latch = !rst && start && s.idle();
    const ActivationRow& act = latch ? act_i[r].read() : kNone;  // read only where the search takes it
    if (latch && act.columns() != s.config().columns)            // a testbench error, reported as in AddressSearch
      SC_REPORT_ERROR("rangesim/row_readout_array",
                      ("row " + std::to_string(r) + ": act_i has " + std::to_string(act.columns()) +
                       " columns, expected " + std::to_string(s.config().columns))
                          .c_str());
    else
      s.tick(rst, start, act);
    const AddressSearchPins p = s.pins();
    if (!(p == so)) so = p, changed = true;
    // The centre processor's state (so its outputs) moves only on clear or a streamed bit.
    if (!clear && !in.addr_valid) continue;
    centre_[r].tick(clear, in);
    const CentreProcessorPins c = centre_[r].pins();
    if (c != out_.centre[r]) out_.centre[r] = c, changed = true;
  }
  if (changed) pins_o.write(out_);  // one write per cycle, only when some row's pin moved
}

}  // namespace rangesim::systemc
