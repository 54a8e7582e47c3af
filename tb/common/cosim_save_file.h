#pragma once
// The GTKWave save file of a co-simulation trace (`rangesim cosim --trace FILE.vcd` writes
// FILE.gtkw beside it), so the trace opens arranged for the person checking the RTL:
//  - "clock and reset": the RTL top's clk and rst;
//  - "checked (RTL, then the model's expected value)": every signal the harness traced under
//    `expected` (tb/common/cosim_run.h) right below its RTL counterpart, phases decoded to their
//    names by a translate filter (FILE.<scope>.<name>.txt) applied to both;
//  - one closed group per RTL module instance, in the module tree's order: clk/rst, inputs (_i),
//    outputs (_o), then internal signals; parameters (names starting with a capital) left out.
// The RTL counterpart of expected signal <scope>.<name> is found by the port naming of
// docs/rtl-contract.md: <name>_o, <scope>_<name>_o, <name>, <name>_q or, for a name like
// centre_valid, valid_o; an index in the scope (row3, adc1) picks the generate instance [3], [1];
// the RTL top is searched first. An expected signal without a counterpart is listed alone.
// Open it from the trace's folder: `gtkwave FILE.gtkw`.
#include <string>
#include <vector>

#include "systemc/common/waveform.h"

namespace rangesim::tb {

// Writes <vcd without .vcd>.gtkw and the filters beside `vcd` (already merged); returns the
// names of the files written (for the caller's staging). std::runtime_error on a write error.
std::vector<std::string> write_cosim_save_file(const std::string& vcd,
                                               const std::vector<systemc::Waveform::Signal>& expected);

}  // namespace rangesim::tb
